!> Lines an analysis writes to the .mess (the handler copies them to the run's message
!> file): the renumbering summary, the Newton/contact table of each step, warnings.
module analysis_log
    use kinds, only: i4
    use strings, only: string_t
    implicit none
    private

    !> A growing list of lines.
    type, public :: analysis_log_t
        integer(i4) :: n = 0
        type(string_t), allocatable :: lines(:)
    end type analysis_log_t

    public :: log_add

contains

    !> Appends one line (trailing blanks removed).
    subroutine log_add(log, text)
        type(analysis_log_t), intent(inout) :: log
        character(len=*), intent(in) :: text
        type(string_t), allocatable :: grown(:)
        integer(i4) :: k
        if (.not. allocated(log%lines)) allocate (log%lines(16))
        if (log%n == size(log%lines)) then
            allocate (grown(2 * size(log%lines)))
            do k = 1, log%n
                call move_alloc(log%lines(k)%s, grown(k)%s)
            end do
            call move_alloc(grown, log%lines)
        end if
        log%n = log%n + 1
        log%lines(log%n)%s = trim(text)
    end subroutine log_add

end module analysis_log
