!> Locating an error found by a lower layer at the deck keyword it concerns: the command
!> handlers of every layer (mesh, model, post, output) report a failure of the code they
!> call at the keyword of the deck that caused it, with the lower layer's message.
module keyword_relocation
    use status, only: status_t
    use strings, only: starts_with
    use deck_command, only: keyword_set_t
    implicit none
    private

    public :: relocate_error

contains

    !> Re-reports a failed status at keyword `key` of `kws` (deck file, line, column,
    !> COMMAND/FACTOR/KEY), keeping its category and message. A lower layer that named a
    !> more precise keyword of the same factor (st%keyword = 'FACTOR/KEY') wins over `key`.
    !> Does nothing when st is ok.
    !>  kws : in, the command or factor occurrence;  key : in, default keyword
    !>  st  : inout, the status to relocate
    subroutine relocate_error(kws, key, st)
        class(keyword_set_t), intent(in) :: kws
        character(len=*), intent(in) :: key
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: message, where
        integer :: code
        if (st%ok()) return
        code = st%code
        message = 'unspecified failure'
        if (allocated(st%message)) message = st%message
        where = trim(key)
        if (allocated(st%keyword) .and. allocated(kws%scope)) then
            if (len(kws%scope) > 0 .and. starts_with(st%keyword, kws%scope // '/')) then
                where = st%keyword(len(kws%scope) + 2:)
                if (.not. kws%has(where)) where = trim(key)
            end if
        end if
        call kws%error_at(where, message, st, code=code)
    end subroutine relocate_error

end module keyword_relocation
