!> MECA_STATIQUE core: linear statics at a list of instants. The stiffness does not depend
!> on the instant: it is assembled and factored once; per instant the imposed values are
!> put into u, then K_ff u_f = f_ext,f - K_fi u_i is solved as u_f = K^-1 (f_ext - f_int(u))
!> from u_f = 0 (elimination of the imposed equations; reactions = f_int - f_ext there),
!> followed by REFINEMENT_STEPS corrections with the same factor; the plates' and plane
!> solids' element matrices are computed once (linear_cache_t) for the assembly and every
!> internal-force evaluation. Bodies held only by
!> springs have their rigid modes kept apart (analysis_solver open_solver: the two-level
!> solver); the plates and plane solids then see u minus those modes (u_body), so their
!> forces, and the residual of the refinement, carry no round-off of the rigid motion.
!> The .mess says how many digits each answer holds: a last solve with the final residual
!> estimates its error (answer_digits).
!> Discretes with SYME='NON' and a matrix that is not symmetric: the factor is of the
!> symmetric part, every solve corrected to one with K (unsymmetric_correction).
!> DIS_CHOC is not a MECA_STATIQUE behaviour: s%choc must be all .false. (springs linear).
!> The .mess ends with the wall and CPU time of each phase (numbering and the solver's
!> analysis, assembly, factorization with its pivot diagnosis, loads and solves): what
!> doc/performance.md's benchmarks read.
module linear_static
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_SINGULAR
    use strings, only: to_text
    use sparse_matrix, only: sym_matrix_t, sym_move
    use direct_solver, only: direct_solver_t, solver_options_t
    use solver_factory, only: assembly_renum
    use assembly_system, only: structure_t, assembly_map_t, build_assembly_map, &
        gather_free, scatter_free, linear_cache_t, build_linear_cache, body_product, &
        linear_product
    use assembly_loads, only: mark_imposed
    use analysis_excitation, only: excitation_t, loads_at, recorded_internal_forces
    use analysis_relations, only: prepare_relations, relations_at
    use assembly_relations, only: elimination_t
    use analysis_solver, only: factor_and_diagnose_linear, open_solver, log_numbering, &
        solve_held, held_t, answer_digits, real_digits
    use two_level_solver, only: from_hat, hat_body_part
    use unsymmetric_correction, only: skew_correction_t, skew_prepare, skew_correct
    use assembly_unsymmetric, only: first_unsymmetric_cell
    use strings, only: real_short
    use analysis_result, only: result_concept_t, result_init, result_store
    use analysis_log, only: analysis_log_t, log_add
    use progress, only: progress_t, progress_note
    implicit none
    private

    public :: meca_statique

    !> Iterative refinement after the direct solve: the pivots of a stiff plate on soft
    !> springs lose ~9 digits (SSNL130), so one solve is only good to ~1e-6 relative; one
    !> correction with the residual recomputed from the elements recovers them (measured on
    !> the bilateral SSNL130 bed: 7.1e-7 -> 4e-8 from the rigid-plate answer).
    integer(i4), parameter :: REFINEMENT_STEPS = 1

contains

    !> f_int(u): the plates and plane solids from their kept matrices at u_body (body_product;
    !> the forces cell_response gives, bit for bit), the other cells (springs, discretes)
    !> at u; work is (n_equations) scratch.
    subroutine static_internal_forces(s, map, cache, u, u_body, fint, work, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(linear_cache_t), intent(inout) :: cache
        real(dp), intent(in) :: u(:), u_body(:)
        real(dp), intent(out) :: fint(:), work(:)
        type(status_t), intent(out) :: st
        call body_product(s, map, cache, u_body, fint, st)
        if (st%ok()) call linear_product(s, map, cache, u, work, st, support_only=.true.)
        if (st%ok()) fint = fint + work
    end subroutine static_internal_forces

    !> Runs MECA_STATIQUE.
    !>  s       : in, the structure (no DIS_CHOC cell)
    !>  excit   : in, EXCIT occurrences
    !>  times   : in, the instants computed (one result each, NUME_ORDRE 1, 2, ...)
    !>  options : in, SOLVEUR (METHODE, RENUM, NPREC, STOP_SINGULIER)
    !>  res     : out, evol_elas with DEPL, FORC_NODA, REAC_NODA
    !>  log     : inout, .mess lines
    !>  st      : out, STATUS_MODEL_ERROR with DIS_CHOC cells, STATUS_SINGULAR, load errors
    !>  progress : in, optional, the run's reporter (a line when it starts, the factorization)
    subroutine meca_statique(s, excit, times, options, res, log, st, progress)
        type(structure_t), intent(in) :: s
        type(excitation_t), intent(in) :: excit(:)
        real(dp), intent(in) :: times(:)
        type(solver_options_t), intent(in) :: options
        type(result_concept_t), intent(out) :: res
        type(analysis_log_t), intent(inout) :: log
        type(status_t), intent(out) :: st
        class(progress_t), pointer, intent(in), optional :: progress
        type(assembly_map_t) :: map
        type(sym_matrix_t) :: matrix
        class(direct_solver_t), allocatable :: solver
        type(held_t) :: held
        logical, allocatable :: imposed(:), rigid(:)
        real(dp), allocatable :: u(:), u_body(:), fint(:), fext(:), r(:), x(:), du(:), &
            forc(:)
        type(elimination_t) :: elim
        type(skew_correction_t) :: skew
        type(linear_cache_t) :: cache
        integer(i4) :: k, n_eq, pass
        real(dp) :: clock(2, 4), assembly_time(2)     ! (wall, CPU) at the phases' ends
        real(dp) :: cache_clock(2)                    ! after the element matrices
        if (any(s%choc)) then
            call set_error(st, STATUS_MODEL_ERROR, 'MECA_STATIQUE is linear: DIS_CHOC ' // &
                'springs need STAT_NON_LINE')
            return
        end if
        call read_clocks(clock(:, 1))
        n_eq = s%dofs%n_equations
        if (present(progress)) call progress_note(progress, 'MECA_STATIQUE: ' // &
            to_text(n_eq) // ' equations, ' // to_text(size(times, kind=i4)) // ' instant(s)')
        allocate (imposed(n_eq), source=.false.)
        do k = 1, size(excit)
            call mark_imposed(s, excit(k)%load, imposed, st)
            if (st%failed()) return
        end do
        call prepare_relations(s, excit, imposed, elim, rigid, st)
        if (st%failed()) return
        call build_assembly_map(s, imposed, assembly_renum(options), map, st, elim, rigid)
        if (st%failed()) return
        call log_numbering(map, options, log)
        call sym_move(map%pattern, matrix)
        call open_solver(s, map, options, matrix, solver, log, st)
        if (present(progress) .and. st%ok()) solver%progress => progress
        if (st%failed()) return
        allocate (u(n_eq), u_body(n_eq), fint(n_eq), fext(n_eq), forc(n_eq), r(map%n_free), &
            x(map%n_free), du(n_eq))
        u = 0.0_dp
        call read_clocks(clock(:, 2))
        ! the plates' and plane solids' matrices, once: the assembly and every internal
        ! force evaluation below take them from here
        call build_linear_cache(s, map, cache, st)
        if (st%failed()) return
        call read_clocks(cache_clock)
        call factor_and_diagnose_linear(s, map, u, matrix, solver, held, options, log, st, &
            assembly_time, cache)
        ! the element matrices are the assembly's work
        assembly_time = assembly_time + cache_clock - clock(:, 2)
        if (st%code == STATUS_SINGULAR .and. first_unsymmetric_cell(s) > 0) &
            call set_error(st, st%code, st%message // ' (with discretes of SYME=''NON'' ' // &
                'parasol factors the symmetric part of K, (K + K^T)/2, and corrects for the ' // &
                'rest: that part must be regular even where K is)')
        if (st%failed()) return
        ! discretes with SYME='NON': K = S + skew part, S factored (unsymmetric_correction)
        call skew_prepare(s, map, matrix, solver, held, options, times(1), log, skew, st)
        if (st%failed()) return
        call read_clocks(clock(:, 3))
        call result_init(res, 'evol_elas', s%mesh, s%dofs, int(size(times), i4))
        do k = 1, int(size(times), i4)
            u = 0.0_dp
            call loads_at(s, excit, times(k), u, fext, st)
            if (st%ok()) call relations_at(s, excit, map, times(k), u, st)
            u_body = u
            if (st%ok()) call static_internal_forces(s, map, cache, u, u_body, fint, forc, st)
            if (st%failed()) return
            do pass = 1, 2 + REFINEMENT_STEPS
                call gather_free(map, fext - fint, r)
                call solve_held(s, map, matrix, solver, held, r, times(k), log, st)
                if (st%failed()) return
                call skew_correct(map, solver, skew, r)
                call from_hat(solver, r, x)
                ! the last solve only estimates the error of the answer
                if (pass == 2 + REFINEMENT_STEPS) exit
                call scatter_free(map, x, du)
                u = u + du
                call hat_body_part(solver, r, x)
                call scatter_free(map, x, du)
                u_body = u_body + du
                call static_internal_forces(s, map, cache, u, u_body, fint, forc, st)
                if (st%failed()) return
            end do
            call recorded_internal_forces(s, times(k), fint, forc, st)   ! less thermal forces
            if (st%failed()) return
            call result_store(res, k, times(k), u, forc, merge(fint - fext, 0.0_dp, &
                map%constrained))
            call log_add(log, 'INST ' // to_text(times(k)) // ': solved; the answer holds ' &
                // real_digits(answer_digits(x, u)) // ' significant digits (correction ' // &
                'for the final residual ' // real_short(maxval(abs(x), dim=1)) // &
                ' against the largest displacement ' // real_short(maxval(abs(u), dim=1)) &
                // ')')
        end do
        if (len(solver%iteration_summary()) > 0) call log_add(log, solver%iteration_summary())
        call read_clocks(clock(:, 4))
        call log_add(log, 'MECA_STATIQUE times (wall / CPU s): numbering and analysis ' // &
            pair(clock(:, 2) - clock(:, 1)) // ', assembly ' // pair(assembly_time) // &
            ', factorization ' // pair(clock(:, 3) - clock(:, 2) - assembly_time) // &
            ', loads and solves ' // pair(clock(:, 4) - clock(:, 3)))
    end subroutine meca_statique

    ! Wall-clock and process CPU seconds now.
    subroutine read_clocks(now)
        real(dp), intent(out) :: now(2)
        integer(i8) :: ticks, rate
        call system_clock(ticks, rate)
        now(1) = real(ticks, dp) / real(max(rate, 1_i8), dp)
        call cpu_time(now(2))
    end subroutine read_clocks

    ! 'wall / CPU' seconds for the .mess.
    function pair(t) result(text)
        real(dp), intent(in) :: t(2)
        character(len=:), allocatable :: text
        text = seconds_text(t(1)) // ' / ' // seconds_text(t(2))
    end function pair

    ! Seconds with 3 decimals (a negative round-off shown as 0).
    function seconds_text(t) result(text)
        real(dp), intent(in) :: t
        character(len=:), allocatable :: text
        character(len=32) :: buf
        write (buf, '(f0.3)') max(t, 0.0_dp)
        text = trim(buf)
        if (text(1:1) == '.') text = '0' // text
    end function seconds_text

end module linear_static
