!> parasol-bench KIND [options]: benchmarks that measure, never gate (doc/performance.md).
program parasol_bench
    use cli_bench, only: run_parasol_bench
    implicit none
    integer :: exit_status
    call run_parasol_bench(exit_status)
    stop exit_status, quiet=.true.
end program parasol_bench
