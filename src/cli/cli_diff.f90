!> parasol-diff command line (listings.md): not built yet.
module cli_diff
    use, intrinsic :: iso_fortran_env, only: error_unit
    implicit none
    private
    public :: run_parasol_diff
contains
    !> Compares two listings; returns 0 same, 1 different or error.
    subroutine run_parasol_diff(exit_status)
        integer, intent(out) :: exit_status
        write (error_unit, '(a)') 'parasol-diff: error: not implemented yet'
        exit_status = 1
    end subroutine run_parasol_diff
end module cli_diff
