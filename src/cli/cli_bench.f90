!> parasol-bench command line: one subcommand per benchmark (doc/performance.md).
module cli_bench
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use strings, only: string_t
    use cli_args, only: get_arguments
    use bench_formula, only: run_formula_bench
    implicit none
    private
    public :: run_parasol_bench
contains
    !> Runs the benchmark named by the first argument; returns 0, or 1 on bad usage.
    subroutine run_parasol_bench(exit_status)
        integer, intent(out) :: exit_status
        type(string_t), allocatable :: args(:)
        call get_arguments(args)
        exit_status = 1
        if (size(args) == 0) then
            call print_bench_usage(error_unit)
            return
        end if
        select case (args(1)%s)
        case ('--help', '-h')
            call print_bench_usage(output_unit)
            exit_status = 0
        case ('formula')
            call run_formula_bench(bench_count(args), exit_status)
        case default
            write (error_unit, '(a)') 'parasol-bench: error: unknown benchmark "' // &
                args(1)%s // '"'
            call print_bench_usage(error_unit)
        end select
    end subroutine run_parasol_bench

    !> Optional evaluation count (second argument), 0 when absent or not a number.
    integer function bench_count(args)
        type(string_t), intent(in) :: args(:)
        integer :: ios
        bench_count = 0
        if (size(args) >= 2) read (args(2)%s, *, iostat=ios) bench_count
    end function bench_count

    subroutine print_bench_usage(unit)
        integer, intent(in) :: unit
        write (unit, '(a)') 'usage: parasol-bench KIND [options]', &
            '  formula [N]   FORMULE evaluations per second (N per formula)', &
            '  (benchmarks are added with the layers they measure)'
    end subroutine print_bench_usage
end module cli_bench
