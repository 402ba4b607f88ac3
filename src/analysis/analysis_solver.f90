!> The direct solver as the analyses use it (MECA_STATIQUE and STAT_NON_LINE): opening the
!> back-end of SOLVEUR (open_solver), assembling and factoring a matrix without stopping,
!> classifying its pivots against NPREC (free, ill-conditioned, regular: doc/analysis.md,
!> "Diagnosis"), reporting a flagged factorization (STATUS_SINGULAR or a warning), solving
!> with held equations when the singularity check is off (METHODE='MUMPS', NPREC < 0), and
!> the solver lines of the .mess (factorizations, the largest loss of digits).
module analysis_solver
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_SINGULAR
    use strings, only: to_text, real_e13, real_short
    use model_dof_numbering, only: describe_equation
    use sparse_matrix, only: sym_matrix_t, sym_diagonal
    use direct_solver, only: direct_solver_t, solver_options_t, factor_report_t, &
        effective_nprec, check_disabled, nprec_text
    use solver_factory, only: create_solver
    use two_level_solver, only: two_level_solver_t, wrap_solver, set_modes, &
        isolate_anchors, set_coarse, to_hat, hat_product
    use assembly_system, only: structure_t, assembly_map_t, assemble_stiffness, &
        renumbering_lines, linear_cache_t, contact_history_t, support_product
    use rigid_bodies, only: rigid_modes_t, find_rigid_modes
    use huge_pages, only: advise_huge_pages
    use analysis_log, only: analysis_log_t, log_add
    use number_limits, only: is_finite, MAX_BINARY_EXPONENT
    use progress, only: progress_update
    implicit none
    private

    !> A pivot below this fraction of the largest diagonal term is at the round-off level
    !> of the stiffest terms (~45 machine epsilons): a free rigid motion, even when the
    !> equation's own diagonal is small enough for NPREC not to flag it (e.g. a DX left free
    !> under a plate 1e8 times stiffer than its springs). Not larger: on fine plates the
    !> rotation diagonals (~D/h) are legitimately far below the membrane ones (~E h); the
    !> 128 x 512 SSNL130 plate has regular DRY pivots at 9.3e-13 of the largest term.
    real(dp), parameter, public :: RIGID_PIVOT_RATIO = 1.0e-14_dp
    !> A pivot that lost at least this many of the ~16 significant digits is at round-off
    !> level: the equation is free (a rigid motion or mechanism), whatever NPREC says. A
    !> pivot that only exceeds NPREC (8 by default, Code_Aster SOLVEUR/NPREC) is an
    !> ill-conditioned but regular matrix: SSNL130's plate ~1e10 N/m on springs ~1e2 N/m
    !> loses ~8-9 digits, which is why Code_Aster's SSNL130 sets NPREC = 9.
    real(dp), parameter, public :: FREE_PIVOT_DIGITS = 12.0_dp
    !> Pivot classes (classify_pivots).
    integer(i4), parameter, public :: PIVOT_REGULAR = 0, PIVOT_ILL_CONDITIONED = 1, &
        PIVOT_FREE = 2
    !> Class of a matrix not factored yet (newton_state_t%elastic_kind).
    integer(i4), parameter, public :: PIVOT_UNKNOWN = -1

    !> A held equation is loaded when the penalty holding it carries more than this fraction
    !> of the largest right-hand-side term: the free motion there is driven, not idle ...
    real(dp), parameter :: HELD_LOAD_RATIO = 1.0e-8_dp
    !> ... and more than the round-off of the product A x, this many times
    !> eps max|a_jj| max|x| (a solve that loses ~9 digits leaves residuals of that order:
    !> model B's idle DX carried 1.9e-7 N against 2.2 N of load).
    real(dp), parameter :: HELD_ROUNDOFF_FACTOR = 1.0e3_dp
    !> Held equations named in the .mess before the list is cut.
    integer(i4), parameter :: LIST_EQUATIONS = 6

    !> Equations held at zero because the singularity check is off (METHODE='MUMPS' with
    !> NPREC < 0, Code_Aster U4.50.01): free equations nothing loads are solved with zero
    !> displacement and named once in the .mess; a loaded one stops the analysis.
    type, public :: held_t
        integer(i4), allocatable :: equations(:)   !< free numbering, of the current factor
        logical :: warned = .false.
    end type held_t

    !> What the factorization of a matrix says about its pivots.
    type, public :: pivot_diagnosis_t
        integer(i4) :: kind = PIVOT_REGULAR
        character(len=:), allocatable :: where     !< node, component and digits lost
        integer(i4) :: n_flagged = 0
        integer(i4) :: nprec = 8
        !> solver diagnostics of the factorization (style.md: digits lost, pivot range)
        real(dp) :: digits = 0.0_dp                !< largest digits lost
        logical :: digits_known = .true.           !< .false.: MUMPS (no pivot access)
        character(len=:), allocatable :: digits_at !< node and component of that pivot
        real(dp) :: min_pivot = 0.0_dp, max_pivot = 0.0_dp   !< range of |pivot|
    end type pivot_diagnosis_t

    !> The solver diagnostics over several factorizations (style.md: digits lost, pivot
    !> range): the largest loss of digits, where, and the range of |pivot|.
    type, public :: pivot_record_t
        real(dp) :: max_digits_lost = 0.0_dp
        character(len=:), allocatable :: digits_at
        real(dp) :: min_pivot = huge(1.0_dp), max_pivot = 0.0_dp
        !> a factorization gave no pivots (MUMPS): its loss is only checked against NPREC
        !> by the back-end's null-pivot detection
        logical :: pivots_unknown = .false.
    end type pivot_record_t

    public :: open_solver, log_numbering, factor_and_diagnose_linear, assemble_and_factor, &
        factor_and_classify, classify_pivots, report_pivots, solve_held, accumulate_pivots, &
        solver_diagnostics_line, real_digits, modes_support, answer_digits

contains

    !> Creates the solver of SOLVEUR (create_solver) and analyses the pattern once. The
    !> solver never stops on a flagged pivot (the analysis classifies them); with the check
    !> off (check_disabled) it holds the free pivots (FREE_PIVOT_DIGITS, RIGID_PIVOT_RATIO).
    !> Bodies held only by springs (rigid_bodies) get a two-level solver that keeps their
    !> rigid modes apart (two_level_solver; doc/analysis.md "Rigid modes"): what is factored
    !> is then the bodies held at their anchors, and NPREC judges that.
    !>  s, map : in, the structure and its numbering (the bodies and their modes)
    !>  st : out, a RENUM the method lacks, a back-end that cannot load or analyse
    subroutine open_solver(s, map, options, matrix, solver, log, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(solver_options_t), intent(in) :: options
        type(sym_matrix_t), intent(in) :: matrix
        class(direct_solver_t), allocatable, intent(out) :: solver
        type(analysis_log_t), intent(inout) :: log
        type(status_t), intent(out) :: st
        type(solver_options_t) :: lenient
        type(rigid_modes_t) :: modes
        class(direct_solver_t), allocatable :: inner
        character(len=:), allocatable :: text
        lenient = options
        lenient%stop_singular = .false.
        if (check_disabled(options)) then
            lenient%hold_digits = FREE_PIVOT_DIGITS
            lenient%hold_ratio = RIGID_PIVOT_RATIO
        end if
        call create_solver(lenient, inner, st)
        if (st%failed()) return
        call find_rigid_modes(s, map, modes, log, st)
        if (st%failed()) return
        if (modes%n_modes > 0) then
            call wrap_solver(inner, solver)
            select type (solver)
            type is (two_level_solver_t)
                call set_modes(solver, modes%r, modes%anchors, st)
            end select
            if (st%failed()) return
        else
            call move_alloc(inner, solver)
        end if
        call solver%analyse(matrix, st)
        if (st%failed()) return
        text = 'SOLVEUR: METHODE ' // trim(solver%options%method) // ', RENUM ' // &
            trim(solver%options%renum) // ', NPREC ' // to_text(options%nprec)
        if (check_disabled(options)) text = text // ' (singularity check off)'
        text = text // ', factor ' // real_short(real(solver%memory_estimate(), dp) / &
            1.0e6_dp) // ' MB'
        if (solver%factor_flops > 0.0_dp) text = text // ', ' // &
            real_short(solver%factor_flops) // ' flop'
        call log_add(log, text // ' estimated')
    end subroutine open_solver

    !> K_s R for the solver's rigid modes: the springs' stiffness at u (elastic or at their
    !> status there: as assemble_stiffness) times the modes; an empty array without modes.
    !> (R is the solver's own, not copied: n x m terms, 19 MB at 128 x 512.)
    !>  ksr : out, (n_free, m), advised for huge pages
    subroutine modes_support(s, map, solver, u, elastic, ksr, st, history)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        class(direct_solver_t), intent(in) :: solver
        real(dp), intent(in) :: u(:)
        logical, intent(in) :: elastic
        real(dp), allocatable, intent(out) :: ksr(:, :)
        type(status_t), intent(out) :: st
        type(contact_history_t), intent(in), optional :: history
        select type (solver)
        type is (two_level_solver_t)
            if (solver%m > 0) then
                allocate (ksr(solver%n, solver%m))
                call advise_huge_pages(ksr)
                call support_product(s, map, u, elastic, solver%r, ksr, st, history)
                return
            end if
        end select
        allocate (ksr(0, 0))
    end subroutine modes_support

    !> The .mess lines on the numbering: LDLT's renumbering figures (the skyline stores that
    !> envelope), or the method's own ordering.
    subroutine log_numbering(map, options, log)
        type(assembly_map_t), intent(in) :: map
        type(solver_options_t), intent(in) :: options
        type(analysis_log_t), intent(inout) :: log
        character(len=100) :: lines(2)
        if (trim(options%method) == 'LDLT') then
            lines = renumbering_lines(map)
            call log_add(log, lines(1))
            call log_add(log, lines(2))
        else
            call log_add(log, 'METHODE ' // trim(options%method) // ': ' // &
                to_text(map%n_free) // ' free equations, ordered by the solver')
        end if
    end subroutine log_numbering

    !> MECA_STATIQUE: assembles and factors the (linear) stiffness at u; a flagged matrix
    !> is STATUS_SINGULAR or a warning (report_pivots); with the check off (MUMPS, NPREC <
    !> 0) free equations are held instead (solve_held judges them).
    !>  matrix : inout, the pattern in, the assembled matrix out
    !>  solver : inout, analysed (open_solver); factored on return
    !>  held   : out, the held equations
    !>  assembly_time : out, the assembly's wall and CPU seconds (the .mess summary)
    !>  cache  : in, optional, built: the plate and plane matrices are taken from it
    subroutine factor_and_diagnose_linear(s, map, u, matrix, solver, held, options, log, st, &
                                          assembly_time, cache)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        real(dp), intent(in) :: u(:)
        type(sym_matrix_t), intent(inout) :: matrix
        class(direct_solver_t), intent(inout) :: solver
        type(held_t), intent(out) :: held
        type(solver_options_t), intent(in) :: options
        type(analysis_log_t), intent(inout) :: log
        type(status_t), intent(out) :: st
        real(dp), intent(out) :: assembly_time(2)
        type(linear_cache_t), intent(in), optional :: cache
        type(pivot_diagnosis_t) :: diag
        type(pivot_record_t) :: one
        call assemble_and_factor(s, map, u, .false., matrix, solver, diag, st, cache=cache, &
            held=held, log=log, assembly_time=assembly_time)
        if (st%failed()) return
        if (diag%kind /= PIVOT_FREE) call accumulate_pivots(diag, one)
        call log_add(log, solver_diagnostics_line(one, options%nprec, options%method))
        if (diag%kind /= PIVOT_REGULAR .and. .not. check_disabled(options)) &
            call report_pivots(diag, options, 0.0_dp, log, st)
    end subroutine factor_and_diagnose_linear

    !> Assembles the matrix at u (elastic or tangent) in place, factors it without stopping,
    !> and classifies its pivots (classify_pivots).
    !>  diag  : out, PIVOT_REGULAR, PIVOT_ILL_CONDITIONED or PIVOT_FREE, and where
    !>  cache : in, optional, the plate/plane matrices (assemble_stiffness)
    !>  history : in, optional, DIS_CONTACT state at the start of the step
    !>  held  : inout, optional, the equations the factor holds (check off)
    !>  log   : inout, optional, gets the factorization line (method, ordering, size, time)
    !>  assembly_time : out, optional, the assembly's wall and CPU seconds
    subroutine assemble_and_factor(s, map, u, elastic, matrix, solver, diag, st, cache, &
                                   history, held, log, assembly_time)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        real(dp), intent(in) :: u(:)
        logical, intent(in) :: elastic
        type(sym_matrix_t), intent(inout) :: matrix
        class(direct_solver_t), intent(inout) :: solver
        type(pivot_diagnosis_t), intent(out) :: diag
        type(status_t), intent(out) :: st
        type(linear_cache_t), intent(in), optional :: cache
        type(contact_history_t), intent(in), optional :: history
        type(held_t), intent(inout), optional :: held
        type(analysis_log_t), intent(inout), optional :: log
        real(dp), intent(out), optional :: assembly_time(2)
        real(dp), allocatable :: ksr(:, :)
        real(dp) :: cpu0, cpu1
        integer(i8) :: t0, t1, rate
        call progress_update(solver%progress, 'assembly of the ' // &
            trim(merge('elastic', 'tangent', elastic)) // ' matrix')
        call system_clock(t0, rate)
        call cpu_time(cpu0)
        call assemble_stiffness(s, map, u, elastic, matrix, st, cache, history)
        call system_clock(t1)
        call cpu_time(cpu1)
        if (present(assembly_time)) assembly_time = [real(t1 - t0, dp) / &
            real(max(rate, 1_i8), dp), cpu1 - cpu0]
        if (st%failed()) return
        call modes_support(s, map, solver, u, elastic, ksr, st, history)
        if (st%failed()) return
        call factor_and_classify(s, map, matrix, solver, ksr, diag, st, held, log)
    end subroutine assemble_and_factor

    !> Factors the assembled matrix without stopping and classifies its pivots
    !> (classify_pivots); held and log as assemble_and_factor. With rigid modes kept apart
    !> (two_level_solver) the anchors are isolated in the matrix first, and the coarse
    !> matrix formed from ksr = K_s R: its pivots are judged with the factor's.
    !>  matrix : inout, the assembled matrix (anchor rows and columns zeroed on return when
    !>           modes are kept apart)
    !>  ksr    : in, (n_free, m) K_s R at the assembled state (modes_support)
    subroutine factor_and_classify(s, map, matrix, solver, ksr, diag, st, held, log)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(sym_matrix_t), intent(inout) :: matrix
        class(direct_solver_t), intent(inout) :: solver
        real(dp), intent(in) :: ksr(:, :)
        type(pivot_diagnosis_t), intent(out) :: diag
        type(status_t), intent(out) :: st
        type(held_t), intent(inout), optional :: held
        type(analysis_log_t), intent(inout), optional :: log
        type(factor_report_t) :: report
        real(dp) :: largest
        real(dp), allocatable :: pivots(:)
        largest = 0.0_dp
        if (matrix%n > 0) largest = maxval(abs(sym_diagonal(matrix)))
        call progress_update(solver%progress, 'factorization (' // &
            trim(solver%options%method) // ')')
        select type (solver)
        type is (two_level_solver_t)
            call isolate_anchors(solver, matrix)
        end select
        call solver%factor(matrix, report, st)
        if (st%failed()) return
        if (present(log)) call log_add(log, factorization_line(report))
        select type (solver)
        type is (two_level_solver_t)
            call set_coarse(solver, ksr, report, st)
            if (st%failed()) return
        end select
        if (present(held)) held%equations = report%held_equations(1:report%n_held)
        if (report%pivots_known) then
            pivots = report%pivots
        else
            allocate (pivots(0))
        end if
        call classify_pivots(report, pivots, largest, solver%options, diag)
        diag%digits = max(report%max_digits_lost, 0.0_dp)
        diag%digits_known = report%pivots_known
        diag%digits_at = ''
        if (report%max_digits_equation > 0) diag%digits_at = describe_equation(s%dofs, &
            s%mesh, map%free_to_eq(report%max_digits_equation))
        diag%min_pivot = report%min_abs_pivot
        diag%max_pivot = report%max_abs_pivot
        if (diag%kind /= PIVOT_REGULAR) diag%where = describe_equation(s%dofs, s%mesh, &
            map%free_to_eq(diag%n_flagged)) // diag%where
        diag%n_flagged = report%n_flagged
    end subroutine factor_and_classify

    !> The significant digits an answer u holds when e estimates its error (the correction
    !> a solve gives for the final residual, computed element by element without the
    !> contrast's cancellation): -log10(max|e| / max|u|), between 0 and -log10(eps).
    pure real(dp) function answer_digits(e, u) result(digits)
        real(dp), intent(in) :: e(:), u(:)
        real(dp) :: top, err
        digits = -log10(epsilon(1.0_dp))
        if (size(u) == 0) return
        top = maxval(abs(u))
        err = maxval(abs(e))
        if (.not. top > 0.0_dp) return
        if (err > epsilon(1.0_dp) * top) digits = max(0.0_dp, -log10(err / top))
    end function answer_digits

    !> One .mess line per factorization: method, ordering, factor size, memory and time.
    function factorization_line(report) result(text)
        type(factor_report_t), intent(in) :: report
        character(len=:), allocatable :: text
        character(len=16) :: buf
        write (buf, '(f0.3)') report%seconds
        if (buf(1:1) == '.') buf = '0' // buf(1:15)
        text = '  factorization ' // report%method // ' (ordering ' // report%ordering // &
            '): ' // to_text(report%factor_entries) // ' terms, ' // &
            real_short(real(report%memory_bytes, dp) / 1.0e6_dp) // ' MB, ' // trim(buf) // ' s'
    end function factorization_line

    !> Classifies a factorization (doc/analysis.md, "Diagnosis"): PIVOT_FREE when a pivot
    !> lost >= FREE_PIVOT_DIGITS digits (zero included) or is below RIGID_PIVOT_RATIO of
    !> the largest diagonal term (round-off level: a free motion); PIVOT_ILL_CONDITIONED
    !> when pivots only exceed NPREC; PIVOT_REGULAR otherwise. On return diag%n_flagged
    !> holds the equation to name (free numbering) and diag%where the pivot text after it.
    !> With the check off (check_disabled) the solver reports only the pivots it held.
    subroutine classify_pivots(report, pivots, largest, options, diag)
        type(factor_report_t), intent(in) :: report
        real(dp), intent(in) :: pivots(:), largest
        type(solver_options_t), intent(in) :: options
        type(pivot_diagnosis_t), intent(inout) :: diag
        integer(i4) :: rigid, eq
        diag%nprec = effective_nprec(options)
        diag%kind = PIVOT_REGULAR
        rigid = 0
        if (size(pivots) > 0) rigid = findloc(abs(pivots) <= RIGID_PIVOT_RATIO * largest, &
            .true., dim=1)
        eq = report%max_digits_equation
        if (report%max_digits_lost >= FREE_PIVOT_DIGITS .and. eq > 0) then
            diag%kind = PIVOT_FREE
        else if (rigid > 0) then
            diag%kind = PIVOT_FREE
            diag%n_flagged = rigid
            diag%where = ' (pivot ' // real_e13(pivots(rigid)) // ' against a largest ' // &
                'diagonal term ' // real_e13(largest) // ')'
            return
        else if (report%n_flagged > 0) then
            diag%kind = PIVOT_ILL_CONDITIONED
            if (.not. report%max_digits_lost > real(diag%nprec, dp)) &
                eq = report%flagged_equations(1)
        else
            return
        end if
        diag%n_flagged = eq
        diag%where = ' (pivot lost ' // real_digits(max(report%max_digits_lost, 0.0_dp)) // &
            ' digits, NPREC = ' // nprec_text(options) // ')'
        if (check_disabled(options)) diag%where = ' (pivot held: NPREC < 0, check off)'
    end subroutine classify_pivots

    !> A flagged matrix that is not an iterate's overshoot: STATUS_SINGULAR (STOP_SINGULIER
    !> = OUI) or a warning line (NON). A free pivot means a missing support or stiffness;
    !> an ill-conditioned one means the model's stiffness contrast exceeds NPREC.
    subroutine report_pivots(diag, options, t, log, st)
        type(pivot_diagnosis_t), intent(in) :: diag
        type(solver_options_t), intent(in) :: options
        real(dp), intent(in) :: t
        type(analysis_log_t), intent(inout) :: log
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: text
        if (diag%kind == PIVOT_FREE) then
            text = 'singular matrix at ' // diag%where // ', ' // to_text(max(diag%n_flagged, &
                1_i4)) // ' pivot(s) flagged: the equation is free (round-off pivot); a ' // &
                'support (DDL_IMPO) or a stiffness is missing there'
        else
            text = 'ill-conditioned matrix at ' // diag%where // ': more than NPREC but ' // &
                'fewer than ' // real_digits(FREE_PIVOT_DIGITS) // ' digits lost, so the ' // &
                'structure is held but its stiffness contrast costs that many digits; ' // &
                'if the contrast is expected raise SOLVEUR/NPREC (Code_Aster''s SSNL130 ' // &
                'uses NPREC = 9)'
            if (options%stop_singular) text = text // ', or set STOP_SINGULIER = ''NON''' &
                // ' to go on with a warning'
        end if
        if (options%stop_singular) then
            call set_error(st, STATUS_SINGULAR, 'INST ' // real_e13(t) // ': ' // text)
        else
            call log_add(log, '  warning (STOP_SINGULIER = NON): ' // text)
        end if
    end subroutine report_pivots

    !> Solves with the factor; with held equations (check off) the penalty that holds each
    !> one must carry (almost) nothing: then the equation is free and unloaded, solved with
    !> zero displacement and named once in the .mess; otherwise a load drives a free
    !> motion and STATUS_SINGULAR names its node and component. With rigid modes kept apart
    !> the solution is in hat coordinates (two_level_solver: from_hat gives the
    !> displacements, hat_body_part what the bodies see).
    !>  r : inout, right-hand side (free equations) in, solution out (hat coordinates)
    !>  loaded_at : out, optional: when given, a loaded held equation is not an error; it is
    !>              named here (node, component, load carried) and r is zeroed; unallocated
    !>              when no held equation is loaded
    subroutine solve_held(s, map, matrix, solver, held, r, t, log, st, loaded_at)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(sym_matrix_t), intent(in) :: matrix
        class(direct_solver_t), intent(inout) :: solver
        type(held_t), intent(inout) :: held
        real(dp), intent(inout) :: r(:)
        real(dp), intent(in) :: t
        type(analysis_log_t), intent(inout) :: log
        type(status_t), intent(out) :: st
        character(len=:), allocatable, intent(out), optional :: loaded_at
        real(dp), allocatable :: rhs(:), ax(:)
        real(dp) :: scale, carried, roundoff
        integer(i4) :: k, eq, worst
        logical :: have_held
        have_held = .false.
        if (allocated(held%equations)) have_held = size(held%equations) > 0
        allocate (rhs(size(r)))
        call to_hat(solver, r, rhs)
        r = rhs
        call solve_in_range(s, map, matrix, solver, r, t, st)
        if (st%failed() .or. .not. have_held) return
        allocate (ax(size(r)))
        call hat_product(solver, matrix, r, ax)
        scale = maxval(abs(rhs))
        roundoff = HELD_ROUNDOFF_FACTOR * epsilon(1.0_dp) * maxval(abs(sym_diagonal(matrix))) &
            * maxval(abs(r))
        worst = 0
        carried = 0.0_dp
        do k = 1, size(held%equations)
            eq = held%equations(k)
            if (abs(rhs(eq) - ax(eq)) > carried) then
                carried = abs(rhs(eq) - ax(eq))
                worst = eq
            end if
        end do
        if (worst > 0 .and. carried > max(HELD_LOAD_RATIO * scale, roundoff) .and. &
            present(loaded_at)) then
            loaded_at = describe_equation(s%dofs, s%mesh, map%free_to_eq(worst)) // &
                ' (held, carrying ' // real_e13(carried) // ' against ' // real_e13(scale) // ')'
            r = 0.0_dp
            return
        else if (worst > 0 .and. carried > max(HELD_LOAD_RATIO * scale, roundoff)) then
            call set_error(st, STATUS_SINGULAR, 'INST ' // real_e13(t) // ': singular ' // &
                'matrix at ' // describe_equation(s%dofs, s%mesh, map%free_to_eq(worst)) // &
                ': the equation is free (SOLVEUR/NPREC < 0 switched the singularity check ' // &
                'off) and loaded (' // real_e13(carried) // ' against ' // real_e13(scale) // &
                '); a support (DDL_IMPO) or a stiffness is missing there')
            r = 0.0_dp
            return
        end if
        if (.not. held%warned) then
            call log_add(log, '  warning (SOLVEUR/NPREC < 0, singularity check off): ' // &
                to_text(size(held%equations)) // ' free equation(s), unloaded, solved ' // &
                'with zero displacement: ' // held_names(s, map, held%equations))
            held%warned = .true.
        end if
    end subroutine solve_held

    !> solver%solve without overflow (issue 13): the right-hand side is scaled by a power of
    !> two to |r| <= 1 (exact: the solution is bit for bit the unscaled one's, scaled), and
    !> the solution is scaled back only when it fits, with the products K u the analysis
    !> forms from it (number_limits): otherwise STATUS_SINGULAR at the largest component,
    !> a load out of all proportion to what holds the structure there.
    subroutine solve_in_range(s, map, matrix, solver, r, t, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(sym_matrix_t), intent(in) :: matrix
        class(direct_solver_t), intent(inout) :: solver
        real(dp), intent(inout) :: r(:)
        real(dp), intent(in) :: t
        type(status_t), intent(out) :: st
        integer :: shift
        integer(i4) :: worst
        real(dp) :: largest
        shift = 0
        if (size(r) > 0) then
            if (maxval(abs(r)) > 0.0_dp) shift = exponent(maxval(abs(r)))
        end if
        r = scale(r, -shift)
        call solver%solve(r, st)
        if (st%failed() .or. size(r) == 0) return
        worst = int(maxloc(abs(r), dim=1), i4)
        largest = abs(r(worst))
        if (.not. is_finite(largest)) then
            worst = int(findloc(is_finite(r), .false., dim=1), i4)
        else if (largest > 0.0_dp .and. exponent(largest) + shift + &
                 max(0, exponent(maxval(abs(sym_diagonal(matrix))))) <= MAX_BINARY_EXPONENT) then
            r = scale(r, shift)
            return
        else if (.not. largest > 0.0_dp) then
            return
        end if
        call set_error(st, STATUS_SINGULAR, 'INST ' // real_e13(t) // ': the solution at ' // &
            describe_equation(s%dofs, s%mesh, map%free_to_eq(worst)) // ' is beyond ' // &
            'double precision (about 2**' // to_text(exponent(largest) + shift) // &
            ' times the stiffness): the loads are out of all proportion to what holds the ' // &
            'structure there (a support or a stiffness missing, or loads too large)')
        r = 0.0_dp
    end subroutine solve_in_range

    !> Node and component of the first held equations (cut after LIST_EQUATIONS).
    function held_names(s, map, equations) result(text)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        integer(i4), intent(in) :: equations(:)
        character(len=:), allocatable :: text
        integer(i4) :: k
        text = ''
        do k = 1, min(size(equations, kind=i4), LIST_EQUATIONS)
            if (k > 1) text = text // ', '
            text = text // describe_equation(s%dofs, s%mesh, map%free_to_eq(equations(k)))
        end do
        if (size(equations) > LIST_EQUATIONS) text = text // ' ...'
    end function held_names

    !> Folds one factorization's diagnostics into the running ones.
    subroutine accumulate_pivots(diag, acc)
        type(pivot_diagnosis_t), intent(in) :: diag
        class(pivot_record_t), intent(inout) :: acc
        if (diag%digits >= acc%max_digits_lost .or. .not. allocated(acc%digits_at)) then
            acc%max_digits_lost = diag%digits
            acc%digits_at = diag%digits_at
        end if
        acc%min_pivot = min(acc%min_pivot, diag%min_pivot)
        acc%max_pivot = max(acc%max_pivot, diag%max_pivot)
        if (.not. diag%digits_known) acc%pivots_unknown = .true.
    end subroutine accumulate_pivots

    !> The .mess line of solver diagnostics (style.md): the method, the largest loss of
    !> significant digits over the factorizations, where, against NPREC (as given: -1 is
    !> reported as -1, "check off" for MUMPS), and the range of |pivot|. A back-end that
    !> gives no pivots (MUMPS) is said so: the figure is then the coarse matrix's of the
    !> rigid modes (0 without), the factor's loss being checked by MUMPS against NPREC.
    function solver_diagnostics_line(acc, nprec, method) result(text)
        class(pivot_record_t), intent(in) :: acc
        integer(i4), intent(in) :: nprec
        character(len=*), intent(in) :: method
        character(len=:), allocatable :: text
        type(solver_options_t) :: opt
        opt%method = method
        opt%nprec = nprec
        text = 'solver ' // trim(method) // ': largest loss ' // &
            real_digits(acc%max_digits_lost) // ' digits'
        if (allocated(acc%digits_at)) then
            if (len(acc%digits_at) > 0) text = text // ' at ' // acc%digits_at
        end if
        text = text // ' (NPREC ' // to_text(nprec)
        if (check_disabled(opt)) then
            text = text // ': check off'
        else if (nprec <= 0) then
            text = text // ', read as ' // to_text(effective_nprec(opt))
        end if
        if (trim(method) == 'GCPC' .or. trim(method) == 'PETSC') then
            text = text // '; an iterative method: no pivots, only its preconditioner''s ' // &
                'factorization (PRE_COND LDLT_SP, LDLT_DP) is judged against NPREC)'
            return
        end if
        if (acc%pivots_unknown) then
            text = text // '; ' // trim(method) // ' gives no pivots: its null-pivot ' // &
                'detection checked NPREC)'
            return
        end if
        text = text // '), |pivot| from ' // real_short(acc%min_pivot) // ' to ' // &
            real_short(acc%max_pivot)
    end function solver_diagnostics_line

    function real_digits(x) result(text)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: text
        character(len=8) :: buf
        write (buf, '(f5.1)') x
        text = trim(adjustl(buf))
    end function real_digits

end module analysis_solver
