!> The file behind a logical unit for the commands that read or write text on units
!> (LIRE_TABLE, IMPR_TABLE, IMPR_FONCTION): the file bound to it (`--unit N=PATH` or an
!> export file's F line), else `<stem>.<N>` in the output folder (Code_Aster's own tests
!> name their unit files <case>.<N>); unit 8 is the result listing (the `.resu`).
module unit_files
    use kinds, only: i4
    use strings, only: to_text
    use status, only: status_t, set_error, STATUS_IO_ERROR
    use run_context, only: run_context_t
    implicit none
    private

    !> Code_Aster's unit of the result listing (RESULTAT).
    integer, parameter, public :: RESULT_LISTING_UNIT = 8

    public :: unit_file_path, unit_written_in_run, unit_input_path

contains

    !> The file of unit `unit` for writing ('' for the result listing).
    function unit_file_path(ctx, unit) result(path)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: unit
        character(len=:), allocatable :: path
        type(status_t) :: st
        path = ''
        if (unit == RESULT_LISTING_UNIT) return
        if (allocated(ctx%unit_numbers)) then
            if (any(ctx%unit_numbers == unit)) then
                call ctx%unit_path(unit, 'TEXT', path, st)
                if (st%ok()) return
            end if
        end if
        path = ctx%output_path('.' // to_text(int(unit, i4)))
    end function unit_file_path

    !> True when this run wrote `path` (ctx%result_files).
    logical function unit_written_in_run(ctx, path)
        type(run_context_t), intent(in) :: ctx
        character(len=*), intent(in) :: path
        integer :: k
        unit_written_in_run = .false.
        if (.not. allocated(ctx%result_files)) return
        do k = 1, size(ctx%result_files)
            if (ctx%result_files(k)%s == path) unit_written_in_run = .true.
        end do
    end function unit_written_in_run

    !> The file to read for unit `unit`: the bound one, or the one this run wrote on it.
    !>  st : STATUS_IO_ERROR when the unit is neither bound nor written (saying how to bind)
    subroutine unit_input_path(ctx, unit, path, st)
        type(run_context_t), intent(in) :: ctx
        integer, intent(in) :: unit
        character(len=:), allocatable, intent(out) :: path
        type(status_t), intent(inout) :: st
        path = ''
        if (allocated(ctx%unit_numbers)) then
            if (any(ctx%unit_numbers == unit)) then
                call ctx%unit_path(unit, 'TEXT', path, st)
                return
            end if
        end if
        if (unit /= RESULT_LISTING_UNIT) then
            path = ctx%output_path('.' // to_text(int(unit, i4)))
            if (unit_written_in_run(ctx, path)) return
        end if
        path = ''
        call set_error(st, STATUS_IO_ERROR, 'logical unit ' // to_text(int(unit, i4)) // &
            ' is not bound to a file (use --unit ' // to_text(int(unit, i4)) // &
            '=PATH, or an F line of the export file)')
    end subroutine unit_input_path

end module unit_files
