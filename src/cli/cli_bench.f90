!> parasol-bench command line: one subcommand per benchmark (doc/performance.md).
module cli_bench
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use strings, only: string_t
    use cli_args, only: get_arguments
    use bench_mesh, only: run_bench_mesh
    use bench_skyline, only: run_bench_skyline
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
        case ('mesh'); call run_bench_mesh(args(2:), exit_status)
        case ('formula')
            block
                use bench_formula, only: run_formula_bench
                call run_formula_bench(args, exit_status)
            end block
        case ('skyline')
            call run_bench_skyline(args(2:), exit_status)
        case default
            write (error_unit, '(a)') 'parasol-bench: error: unknown benchmark "' // &
                args(1)%s // '"'
            call print_bench_usage(error_unit)
        end select
    end subroutine run_parasol_bench

    subroutine print_bench_usage(unit)
        integer, intent(in) :: unit
        write (unit, '(a)') 'usage: parasol-bench KIND [options]', &
            '  mesh FILE      time reading a mesh (.mail or .msh)', &
            '  formula        FORMULE evaluations per second', &
            '  skyline --nx NX --ny NY --dofs D [--renum RCMK|METIS|SANS]  skyline vs DPBTRF', &
            '  (benchmarks are added with the layers they measure)'
    end subroutine print_bench_usage
end module cli_bench
