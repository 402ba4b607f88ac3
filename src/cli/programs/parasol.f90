!> parasol — runs a Code_Aster-style deck (see doc/ and `parasol --help`).
!> The program only hands over to the cli module; only cli chooses the exit status.
program parasol
    use cli, only: run_parasol
    implicit none
    integer :: exit_status
    call run_parasol(exit_status)
    stop exit_status, quiet=.true.
end program parasol
