!> parasol-diff RESULT REFERENCE [--rtol R] [--atol A]: compares two listings (listings.md).
program parasol_diff
    use cli_diff, only: run_parasol_diff
    implicit none
    integer :: exit_status
    call run_parasol_diff(exit_status)
    stop exit_status, quiet=.true.
end program parasol_diff
