!> parasol-bench formula: speed of compiled FORMULE evaluation (doc/performance.md,
!> "FORMULE evaluation"). Two formulas of the SSNL130 load are compiled from a deck text,
!> bound once to (INST, X, Y, Z), then evaluated many times; evaluations per second printed.
module bench_formula
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit, int64
    use kinds, only: dp
    use strings, only: string_t, to_text
    use status, only: status_t, format_status
    use run_context, only: run_context_t, init_context
    use deck_interpreter, only: deck_from_text, evaluate_deck
    use function_concept, only: function_concept_t, param_binding_t
    use command_registration, only: register_commands
    implicit none
    private
    public :: run_formula_bench

    !> Evaluations per formula (about a second in Release on one core).
    integer, parameter :: DEFAULT_COUNT = 5000000

    character(len=*), parameter :: NL = achar(10)
    character(len=*), parameter :: BENCH_DECK = &
        "def Pression(t,x,y,z):" // NL // &
        "   Pressy = 5.0*(y-2.0)**2" // NL // &
        "   if ( t <= 1.0 ): return Pressy*t" // NL // &
        "   return Pressy" // NL // &
        "PLAIN = FORMULE(VALE='5.0*(Y-2.0)**2*min(INST,1.0)', NOM_PARA=('INST','X','Y','Z'))" &
        // NL // &
        "WITH_DEF = FORMULE(VALE='Pression(INST,X,Y,Z)', NOM_PARA=('INST','X','Y','Z')," // &
        " Pression=Pression)" // NL

contains

    !> parasol-bench formula [N]: N evaluations per formula (default DEFAULT_COUNT).
    !>  args : the command-line arguments (args(1) = 'formula');  exit_status : 0, 1 on error
    subroutine run_formula_bench(args, exit_status)
        type(string_t), intent(in) :: args(:)
        integer, intent(out) :: exit_status
        type(run_context_t) :: ctx
        type(status_t) :: st
        integer :: n, ios
        exit_status = 1
        n = 0
        if (size(args) >= 2) read (args(2)%s, *, iostat=ios) n
        if (n <= 0) n = DEFAULT_COUNT
        call init_context(ctx, 'bench.comm', '')
        call register_commands(ctx)
        call deck_from_text(ctx, BENCH_DECK, st)
        if (st%ok()) call evaluate_deck(ctx, st)
        if (st%failed()) then
            write (error_unit, '(a)') 'parasol-bench formula: ' // format_status(st)
            return
        end if
        call time_formula(ctx, 'PLAIN', '5.0*(Y-2.0)**2*min(INST,1.0)', n, st)
        if (st%ok()) call time_formula(ctx, 'WITH_DEF', 'Pression(INST,X,Y,Z) via def', n, st)
        if (st%failed()) then
            write (error_unit, '(a)') 'parasol-bench formula: ' // format_status(st)
            return
        end if
        exit_status = 0
    end subroutine run_formula_bench

    subroutine time_formula(ctx, name, label, n, st)
        type(run_context_t), intent(in) :: ctx
        character(len=*), intent(in) :: name, label
        integer, intent(in) :: n
        type(status_t), intent(out) :: st
        type(param_binding_t) :: binding
        real(dp) :: values(4), y, total, seconds
        integer(int64) :: t0, t1, rate
        integer :: i, k
        k = ctx%find_symbol(name)
        select type (f => ctx%symbols(k)%value%obj)
        class is (function_concept_t)
            call f%bind(['INST', 'X   ', 'Y   ', 'Z   '], binding)
            total = 0.0_dp
            call system_clock(t0, rate)
            do i = 1, n
                values = [real(mod(i, 200), dp) * 0.01_dp, 0.5_dp, &
                          real(mod(i, 1000), dp) * 0.002_dp, 0.0_dp]
                call f%evaluate(binding, values, y, st)
                if (st%failed()) return
                total = total + y
            end do
            call system_clock(t1)
            seconds = max(real(t1 - t0, dp) / real(rate, dp), 1.0e-9_dp)
            write (output_unit, '(a)') 'formula ' // label // ': ' // to_text(n) // &
                ' evaluations in ' // to_text(seconds) // ' s = ' // &
                to_text(nint(real(n, dp) / seconds, int64)) // ' evaluations/s (checksum ' // &
                to_text(total) // ')'
        end select
    end subroutine time_formula

end module bench_formula
