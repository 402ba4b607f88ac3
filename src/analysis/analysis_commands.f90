!> Command handlers MECA_STATIQUE and STAT_NON_LINE: gather the structure from the MODELE,
!> CHAM_MATER and CARA_ELEM concepts, the EXCIT loads, COMPORTEMENT (DIS_CHOC and
!> DIS_CONTACT cells),
!> INCREMENT, NEWTON, CONVERGENCE and SOLVEUR, run the core (linear_static,
!> contact_newton) and write its lines to the .mess. The result is a result_concept_t.
module analysis_commands
    use kinds, only: dp, i4, i8
    use status, only: status_t, clear_status, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use strings, only: to_text, real_e13
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_command_support, only: group_cells, all_cells
    use mesh_types, only: cell_name, cell_label
    use model_types, only: is_discrete
    use model_concept, only: model_concept_t
    use material_concept, only: material_field_concept_t
    use cara_elem_concept, only: cara_elem_concept_t
    use model_cara_elem, only: cara_elem_init
    use model_material, only: material_field_init
    use load_commands, only: char_meca_concept_t
    use function_concept, only: function_concept_t
    use real_list, only: real_list_t
    use time_stepping, only: list_inst_concept_t, step_cutting_t, step_cutting_for
    use assembly_system, only: structure_t, structure_check
    use assembly_unsymmetric, only: first_unsymmetric_cell
    use assembly_loads, only: check_imposed_owners, record_imposed, follower_refusal
    use model_loads, only: load_item_where
    use function_concept, only: param_binding_t
    use direct_solver, only: solver_options_t
    use solver_factory, only: DEFAULT_METHOD, default_renum, renum_allowed
    use residual_line_search, only: line_search_options_t
    use krylov_solver, only: pre_cond_allowed, algorithm_allowed, KRYLOV_DEFAULT_RESI_RELA
    use contact_newton, only: stat_non_line, newton_options_t, excitation_t, &
        newton_summary_t, solver_diagnostics_line
    use linear_static, only: meca_statique
    use analysis_result, only: result_concept_t, RESULT_INST_PRECISION, result_set_structure, &
        result_continue, result_find
    use analysis_log, only: analysis_log_t, log_stream, log_flush
    implicit none
    private

    public :: run_stat_non_line, run_meca_statique

    !> Most memory an analysis may set aside for what it records: the fields of every
    !> instant (DEPL, FORC_NODA, REAC_NODA, spring states) and the spring statuses of every
    !> Newton iteration of a step. Both are allocated before the first step from counts the
    !> deck gives (instants, ITER_GLOB_MAXI): beyond this they are refused with a message at
    !> the keyword instead of an allocation failure (issue 13).
    integer(i8), parameter :: MAX_RECORD_BYTES = 2_i8**30

contains

    !> STAT_NON_LINE (see contact_newton for the algorithm and its defaults).
    !>  st : out, located errors (concept types, COMPORTEMENT, INCREMENT); analysis failures
    !>       (STATUS_NO_CONVERGENCE, STATUS_NO_EQUILIBRIUM, STATUS_SINGULAR) at the command
    subroutine run_stat_non_line(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(structure_t) :: s
        type(excitation_t), allocatable :: excit(:)
        type(newton_options_t) :: options
        type(result_concept_t), allocatable :: res
        type(analysis_log_t) :: log
        type(newton_summary_t) :: summary
        type(step_cutting_t) :: cutting
        real(dp), allocatable :: times(:)
        type(result_concept_t), pointer :: earlier
        integer(i4) :: k_init
        type(keyword_set_t) :: occ
        character(len=:), allocatable :: message
        call gather_structure(cmd, s, st)
        if (st%ok()) call gather_excitations(cmd, s, excit, st)
        if (st%ok()) call read_behaviour(cmd, s, st)
        if (st%ok()) call read_initial_state(cmd, s, earlier, k_init, st)
        if (st%ok()) then
            if (associated(earlier)) then
                call read_increment(cmd, times, cutting, st, earlier%inst(k_init))
            else
                call read_increment(cmd, times, cutting, st)
            end if
        end if
        if (st%ok()) call read_newton(ctx, cmd, options, st)
        if (st%failed()) return
        options%cutting = cutting
        options%deadline = ctx%deadline            ! polled between Newton iterations
        options%progress => ctx%progress           ! a line per step, work under way
        call structure_check(s, st)
        if (st%ok()) call refuse_unsymmetric(cmd, s, st)
        if (st%ok()) call check_records(cmd, 'INCREMENT', 'LIST_INST', size(times, kind=i8), &
            s%dofs%n_equations, count(s%choc), options%iter_glob_maxi, st)
        if (st%ok()) call check_imposed(s, excit, times(2:), st)
        if (st%failed()) return
        call ctx%write_mess('    ' // to_text(count(s%choc .and. .not. s%dis_contact)) // &
            ' DIS_CHOC cell(s), ' // to_text(count(s%dis_contact)) // ' DIS_CONTACT cell(s), ' &
            // to_text(size(times) - 1) // ' step(s) from INST ' // real_e13(times(1)))
        allocate (res)
        call log_stream(log, ctx%mess, '    ')   ! the .mess grows step by step
        if (associated(earlier)) then
            call ctx%write_mess('    initial state: ' // earlier%type_name() // ' NUME_ORDRE ' &
                // to_text(earlier%nume_ordre(k_init)) // ' at INST ' // &
                real_e13(earlier%inst(k_init)))
            call stat_non_line(s, excit, times, options, res, log, summary, st, &
                earlier%depl(:, k_init))
        else
            call stat_non_line(s, excit, times, options, res, log, summary, st)
        end if
        call log_flush(log)
        if (st%failed()) return
        if (associated(cmd%reuse)) then   ! reuse: earlier is cmd%reuse, changed in place
            call result_continue(earlier, k_init, res, st)
            if (st%failed()) then
                occ = cmd%occurrence('ETAT_INIT', 1)
                message = st%message
                call occ%error_at('EVOL_NOLI', message, st)
            end if
            return                        ! no result: the name stays bound to cmd%reuse
        end if
        call ctx%write_mess('    STAT_NON_LINE: ' // to_text(sum(summary%iterations)) // &
            ' iteration(s), ' // to_text(sum(summary%factorizations)) // &
            ' factorization(s) in ' // to_text(summary%n_steps) // ' step(s)')
        call ctx%write_mess('    contact Newton: ' // to_text(sum(summary%solves)) // &
            ' solve(s) with a factor, ' // to_text(sum(summary%updated)) // &
            ' tangent(s) through another status''s factor, ' // &
            to_text(sum(summary%damped)) // ' correction(s) damped by the line search')
        call ctx%write_mess('    ' // solver_diagnostics_line(summary, options%factor%nprec, &
            options%factor%method))
        call keep_structure(cmd, s, res)
        call move_alloc(res, result)
    end subroutine run_stat_non_line

    ! STAT_NON_LINE factors symmetric tangents only (its contact Newton updates them by
    ! symmetric blocks): a discrete with SYME='NON' and a matrix that is not symmetric is
    ! solved by MECA_STATIQUE (unsymmetric_correction), not here.
    subroutine refuse_unsymmetric(cmd, s, st)
        type(command_t), intent(in) :: cmd
        type(structure_t), intent(in) :: s
        type(status_t), intent(out) :: st
        integer(i4) :: c
        c = first_unsymmetric_cell(s)
        if (c == 0) return
        call cmd%error_at('CARA_ELEM', cell_label(s%mesh, c) // ' has a discrete ' // &
            'stiffness with SYME=''NON'' that is not symmetric: STAT_NON_LINE does not ' // &
            'build unsymmetric tangents; MECA_STATIQUE solves it, or give a symmetric ' // &
            'matrix', st, STATUS_NOT_IMPLEMENTED)
    end subroutine refuse_unsymmetric

    !> MECA_STATIQUE: linear statics at INST / LIST_INST (default: INST = 0).
    subroutine run_meca_statique(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(structure_t) :: s
        type(excitation_t), allocatable :: excit(:)
        type(newton_options_t) :: options
        type(result_concept_t), allocatable :: res
        type(analysis_log_t) :: log
        real(dp), allocatable :: times(:)
        class(concept_t), pointer :: p
        call gather_structure(cmd, s, st)
        if (st%ok()) call gather_excitations(cmd, s, excit, st)
        if (st%ok()) call read_newton(ctx, cmd, options, st)
        if (st%failed()) return
        allocate (s%choc(s%mesh%n_cells), source=.false.)
        times = [0.0_dp]
        if (cmd%has('INST')) call cmd%get_reals('INST', times, st)
        if (cmd%has('LIST_INST')) then
            call cmd%get_concept('LIST_INST', p, st)
            if (st%ok()) then
                select type (p)
                type is (real_list_t)
                    times = p%values
                end select
            end if
        end if
        if (st%failed()) return
        call structure_check(s, st)
        if (st%ok()) call check_records(cmd, '', merge('LIST_INST', 'INST     ', &
            cmd%has('LIST_INST')), size(times, kind=i8), s%dofs%n_equations, 0_i4, 0_i4, st)
        if (st%ok()) call check_imposed(s, excit, times, st)
        if (st%failed()) return
        allocate (res)
        call log_stream(log, ctx%mess, '    ')
        call meca_statique(s, excit, times, options%factor, res, log, st, ctx%progress)
        call log_flush(log)
        if (st%failed()) return
        call keep_structure(cmd, s, res)
        call move_alloc(res, result)
    end subroutine run_meca_statique

    !> Gives the result the structure it was computed on (CALC_CHAMP computes on it) and the
    !> name of its MODELE.
    subroutine keep_structure(cmd, s, res)
        type(command_t), intent(in) :: cmd
        type(structure_t), intent(in) :: s
        type(result_concept_t), intent(inout) :: res
        class(concept_t), pointer :: p
        type(status_t) :: st
        character(len=:), allocatable :: name
        name = ''
        call cmd%get_concept('MODELE', p, st)
        if (st%ok()) then
            if (allocated(p%name)) name = p%name
        end if
        call result_set_structure(res, s%model, s%materials, s%cara, s%choc, name)
    end subroutine keep_structure

    !> Refuses, before anything is allocated, an analysis whose records would take more
    !> than MAX_RECORD_BYTES: n_inst instants of 3 fields of n_eq equations and n_springs
    !> spring states (a logical and a force each), and n_springs statuses and a residual for
    !> each of the iter_max + 1 Newton iterations of a step.
    !>  factor, key : where the instants come from (factor '' = the command level)
    !>  st : out, located at CONVERGENCE/ITER_GLOB_MAXI or at the instants' keyword
    subroutine check_records(cmd, factor, key, n_inst, n_eq, n_springs, iter_max, st)
        type(command_t), intent(in) :: cmd
        character(len=*), intent(in) :: factor, key
        integer(i8), intent(in) :: n_inst
        integer(i4), intent(in) :: n_eq, n_springs, iter_max
        type(status_t), intent(inout) :: st
        type(keyword_set_t) :: occ
        integer(i8) :: per_instant, per_iteration
        real(dp) :: bytes
        per_iteration = int(n_springs, i8) * storage_size(.true.) / 8 + &
            storage_size(1.0_dp) / 8                    ! the statuses, the residual
        bytes = real(per_iteration, dp) * (real(iter_max, dp) + 1.0_dp)
        if (bytes > real(MAX_RECORD_BYTES, dp)) then
            occ = cmd%occurrence('CONVERGENCE', 1)
            call occ%error_at('ITER_GLOB_MAXI', 'ITER_GLOB_MAXI = ' // to_text(iter_max) // &
                ': more iterations than can be recorded (the statuses of ' // &
                to_text(n_springs) // ' springs at each iteration of a step would take ' // &
                gib_text(bytes) // ', more than ' // gib_text(real(MAX_RECORD_BYTES, dp)) &
                // ')', st, code=STATUS_MODEL_ERROR)
            return
        end if
        per_instant = 3_i8 * n_eq * storage_size(1.0_dp) / 8 + &
            int(n_springs, i8) * (storage_size(.true.) + storage_size(1.0_dp)) / 8
        bytes = real(per_instant, dp) * real(n_inst, dp)
        if (bytes > real(MAX_RECORD_BYTES, dp)) then
            if (len(factor) > 0) then
                occ = cmd%occurrence(factor, 1)
            else
                occ = cmd%keyword_set_t
            end if
            call occ%error_at(key, to_text(n_inst) // ' instants: more than can be ' // &
                'recorded (the fields of ' // to_text(n_eq) // ' equations at every ' // &
                'instant would take ' // gib_text(bytes) // ', more than ' // &
                gib_text(real(MAX_RECORD_BYTES, dp)) // ')', st, code=STATUS_MODEL_ERROR)
        end if
    end subroutine check_records

    !> A component imposed twice with different values (in one load or two loads of EXCIT,
    !> FONC_MULT applied) at any instant of the analysis is an error at the occurrence found
    !> second, naming the first: Code_Aster refuses conflicting DDL_IMPO, and imposing them
    !> in turn would silently keep the last.
    !>  times : in, the instants the loads are applied at
    subroutine check_imposed(s, excit, times, st)
        type(structure_t), intent(in) :: s
        type(excitation_t), intent(in) :: excit(:)
        real(dp), intent(in) :: times(:)
        type(status_t), intent(inout) :: st
        real(dp), allocatable :: value(:)
        integer(i4), allocatable :: owner(:, :)
        integer(i4) :: i, k, first(2)
        real(dp) :: factor
        type(param_binding_t) :: binding
        allocate (value(s%dofs%n_equations), owner(2, s%dofs%n_equations))
        do i = 1, size(times)
            owner = 0
            do k = 1, size(excit)
                factor = 1.0_dp
                if (associated(excit(k)%fonc_mult)) then
                    call excit(k)%fonc_mult%bind(['INST'], binding)
                    call excit(k)%fonc_mult%evaluate(binding, [times(i)], factor, st)
                    if (st%failed()) then
                        call clear_status(st)      ! the analysis reports it, located
                        cycle
                    end if
                end if
                call record_imposed(s, excit(k)%load, k, times(i), factor, value, owner, &
                                    first, st)
                if (st%failed()) then
                    if (first(1) > 0) st%message = st%message // ' at ' // &
                        load_item_where(excit(first(1))%load%items(first(2))) // &
                        ' (Code_Aster refuses conflicting imposed values: impose each ' // &
                        'component once)'
                    return
                end if
            end do
        end do
    end subroutine check_imposed

    ! Bytes as GiB with 3 significant digits ("68.0 GiB").
    function gib_text(bytes) result(text)
        real(dp), intent(in) :: bytes
        character(len=:), allocatable :: text
        character(len=16) :: buf
        write (buf, '(f16.1)') bytes / 2.0_dp**30
        text = trim(adjustl(buf)) // ' GiB'
    end function gib_text

    !> MODELE, CHAM_MATER, CARA_ELEM -> the structure (copies).
    subroutine gather_structure(cmd, s, st)
        type(command_t), intent(in) :: cmd
        type(structure_t), intent(out) :: s
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        call cmd%get_concept('MODELE', p, st)
        if (st%failed()) return
        select type (p)
        type is (model_concept_t)
            s%mesh = p%mesh
            s%model = p%model
            s%dofs = p%dofs
        class default
            call cmd%error_at('MODELE', 'expected a model (modele), got ' // p%type_name(), st)
            return
        end select
        call material_field_init(s%materials, s%mesh)
        if (cmd%has('CHAM_MATER')) then
            call cmd%get_concept('CHAM_MATER', p, st)
            if (st%failed()) return
            select type (p)
            type is (material_field_concept_t)
                s%materials = p%field
            class default
                call cmd%error_at('CHAM_MATER', 'expected a material field (cham_mater), ' // &
                    'got ' // p%type_name(), st)
                return
            end select
        end if
        call cara_elem_init(s%cara, s%mesh)
        if (cmd%has('CARA_ELEM')) then
            call cmd%get_concept('CARA_ELEM', p, st)
            if (st%failed()) return
            select type (p)
            type is (cara_elem_concept_t)
                s%cara = p%cara
            class default
                call cmd%error_at('CARA_ELEM', 'expected element characteristics ' // &
                    '(cara_elem), got ' // p%type_name(), st)
                return
            end select
        end if
    end subroutine gather_structure

    !> EXCIT occurrences: CHARGE (char_meca, or char_cine_meca of AFFE_CHAR_CINE) and
    !> optional FONC_MULT. An equation imposed by an AFFE_CHAR_CINE and by another load is an
    !> error at the later EXCIT's CHARGE (check_imposed_owners).
    subroutine gather_excitations(cmd, s, excit, st)
        type(command_t), intent(in) :: cmd
        type(structure_t), intent(in) :: s
        type(excitation_t), allocatable, intent(out) :: excit(:)
        type(status_t), intent(out) :: st
        type(keyword_set_t) :: occ
        class(concept_t), pointer :: p
        integer(i4) :: k
        integer(i4), allocatable :: owner(:)
        allocate (owner(s%dofs%n_equations), source=0_i4)
        allocate (excit(cmd%count('EXCIT')))
        do k = 1, size(excit)
            occ = cmd%occurrence('EXCIT', k)
            call occ%get_concept('CHARGE', p, st)
            if (st%failed()) return
            select type (p)
            type is (char_meca_concept_t)
                excit(k)%load => p%loads
                call check_imposed_owners(s, p%loads, k, owner, st)
                if (st%failed()) then
                    call occ%error_at('CHARGE', st%message, st, code=STATUS_MODEL_ERROR)
                    return
                end if
            class default
                call occ%error_at('CHARGE', 'expected a load (char_meca), got ' // &
                    p%type_name(), st)
                return
            end select
            call read_type_charge(occ, s, excit(k), st)
            if (st%failed()) return
            if (.not. occ%has('FONC_MULT')) cycle
            call occ%get_concept('FONC_MULT', p, st)
            if (st%failed()) return
            select type (p)
            class is (function_concept_t)
                excit(k)%fonc_mult => p
            class default
                call occ%error_at('FONC_MULT', 'expected a function, got ' // p%type_name(), st)
                return
            end select
        end do
    end subroutine gather_excitations

    !> EXCIT/TYPE_CHARGE (STAT_NON_LINE; Code_Aster U4.51.03): FIXE_CSTE (default) and SUIV,
    !> the follower load, for the loads that may follow (assembly_loads follower_refusal);
    !> FIXE_PILO and SUIV_PILO need PILOTAGE, DIDI an initial state: not built.
    subroutine read_type_charge(occ, s, e, st)
        type(keyword_set_t), intent(in) :: occ
        type(structure_t), intent(in) :: s
        type(excitation_t), intent(inout) :: e
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: kind, why
        if (.not. occ%has('TYPE_CHARGE')) return
        call occ%get_text('TYPE_CHARGE', kind, st)
        if (st%failed()) return
        select case (kind)
        case ('FIXE_CSTE')
        case ('SUIV')
            why = follower_refusal(s, e%load)
            if (len(why) > 0) then
                call occ%error_at('TYPE_CHARGE', "TYPE_CHARGE='SUIV': " // why, st, &
                    code=STATUS_NOT_IMPLEMENTED)
                return
            end if
            e%follower = .true.
        case default
            call occ%error_at('TYPE_CHARGE', "TYPE_CHARGE='" // kind // "' is not built in " // &
                "parasol ('FIXE_PILO' and 'SUIV_PILO' are loads driven by PILOTAGE, 'DIDI' " // &
                "differential Dirichlet conditions); 'FIXE_CSTE' and 'SUIV' are", st, &
                code=STATUS_NOT_IMPLEMENTED)
        end select
    end subroutine read_type_charge

    !> COMPORTEMENT: RELATION per cell (TOUT or GROUP_MA; later occurrences win). The contact
    !> laws DIS_CHOC and DIS_CONTACT apply to discrete (DIS_T, 2D_DIS_T) cells only.
    subroutine read_behaviour(cmd, s, st)
        type(command_t), intent(in) :: cmd
        type(structure_t), intent(inout) :: s
        type(status_t), intent(out) :: st
        type(keyword_set_t) :: occ
        character(len=:), allocatable :: relation
        integer(i4), allocatable :: cells(:)
        integer(i4) :: k
        logical :: contact_law
        allocate (s%choc(s%mesh%n_cells), s%dis_contact(s%mesh%n_cells), source=.false.)
        do k = 1, cmd%count('COMPORTEMENT')
            occ = cmd%occurrence('COMPORTEMENT', k)
            call occ%get_text('RELATION', relation, st)
            if (st%failed()) return
            contact_law = relation == 'DIS_CHOC' .or. relation == 'DIS_CONTACT'
            if (occ%has('GROUP_MA')) then
                call group_cells(occ, 'GROUP_MA', s%mesh, cells, st)
                if (st%failed()) return
                if (contact_law .and. .not. all(is_discrete(s%model%element(cells)))) then
                    call occ%error_at('GROUP_MA', relation // ' applies to discrete (DIS_T, ' &
                        // '2D_DIS_T) cells only; ' // to_text(count(.not. is_discrete( &
                        s%model%element(cells)))) // ' cell(s) of the group are not', st, &
                        code=STATUS_MODEL_ERROR)
                    return
                end if
            else
                cells = all_cells(s%mesh)
                if (contact_law) cells = pack(cells, is_discrete(s%model%element))
            end if
            s%choc(cells) = contact_law
            s%dis_contact(cells) = relation == 'DIS_CONTACT'
            if (contact_law) call refuse_friction(occ, s, cells, st)
            if (st%failed()) return
        end do
    end subroutine read_behaviour

    !> ETAT_INIT (Code_Aster's U4.51.03): the stored instant of an EVOL_NOLI made by
    !> STAT_NON_LINE on the same equations, NUME_ORDRE or INST (PRECISION, CRITERE), by
    !> default its last. The fields DEPL, SIGM, VARI are refused at their keyword (parasol
    !> has no field concept to start from). reuse= must name the ETAT_INIT result
    !> (Code_Aster's reentrant='f:ETAT_INIT/EVOL_NOLI'), which the new instants continue.
    !>  earlier : out, the result (null without ETAT_INIT); k : its stored instant
    subroutine read_initial_state(cmd, s, earlier, k, st)
        type(command_t), intent(in) :: cmd
        type(structure_t), intent(in) :: s
        type(result_concept_t), pointer, intent(out) :: earlier
        integer(i4), intent(out) :: k
        type(status_t), intent(out) :: st
        type(keyword_set_t) :: occ
        class(concept_t), pointer :: p
        character(len=:), allocatable :: criterion
        real(dp) :: inst, precision
        integer(i4) :: order
        character(len=*), parameter :: FIELDS(3) = ['DEPL', 'SIGM', 'VARI']
        integer :: i
        earlier => null()
        k = 0
        call clear_status(st)
        if (cmd%count('ETAT_INIT') == 0) then
            if (associated(cmd%reuse)) call cmd%error_at('reuse', 'STAT_NON_LINE continues ' &
                // 'the result it reuses from its state: give it as ETAT_INIT=_F(EVOL_NOLI=' &
                // '...), or leave reuse out for a new result', st)
            return
        end if
        occ = cmd%occurrence('ETAT_INIT', 1)
        do i = 1, size(FIELDS)
            if (occ%has(trim(FIELDS(i)))) then
                call occ%error_at(trim(FIELDS(i)), 'an initial state from a field is not ' // &
                    'built in parasol: give the result it comes from as EVOL_NOLI', st, &
                    code=STATUS_NOT_IMPLEMENTED)
                return
            end if
        end do
        call occ%get_concept('EVOL_NOLI', p, st)
        if (st%failed()) return
        select type (p)
        type is (result_concept_t)
            earlier => p
        end select
        if (.not. associated(earlier)) then
            call occ%error_at('EVOL_NOLI', 'expected a result of STAT_NON_LINE (its ' // &
                'displacements at an instant), got ' // p%type_name(), st)
            return
        end if
        if (associated(cmd%reuse)) then
            if (.not. associated(cmd%reuse, p)) then
                call cmd%error_at('reuse', 'reuse names another result than ' // &
                    'ETAT_INIT/EVOL_NOLI: STAT_NON_LINE continues the result it starts ' // &
                    'from (write reuse= the EVOL_NOLI result, or leave reuse out)', st)
                earlier => null()
                return
            end if
        end if
        if (.not. earlier%has_state .or. earlier%n_stored < 1) then
            call occ%error_at('EVOL_NOLI', 'the result holds no displacements to start from', st)
        else if (earlier%dofs%n_equations /= s%dofs%n_equations) then
            call occ%error_at('EVOL_NOLI', 'the result is on ' // &
                to_text(earlier%dofs%n_equations) // ' equations, this analysis on ' // &
                to_text(s%dofs%n_equations) // ': ETAT_INIT must come from the same model', st)
        else if (occ%has('NUME_ORDRE')) then
            call occ%get_int('NUME_ORDRE', order, st)
            if (st%ok()) call result_find(earlier, k, st, nume_ordre=order)
            if (st%failed()) call relocate('NUME_ORDRE')
        else if (occ%has('INST')) then
            call occ%get_real('INST', inst, st)
            if (st%ok()) call occ%get_real('PRECISION', precision, st)
            if (st%ok()) call occ%get_text('CRITERE', criterion, st)
            if (st%ok()) call result_find(earlier, k, st, inst=inst, precision=precision, &
                criterion=criterion)
            if (st%failed()) call relocate('INST')
        else
            k = earlier%n_stored           ! Code_Aster: the last stored instant
        end if
        if (st%failed()) earlier => null()
    contains
        subroutine relocate(key)
            character(len=*), intent(in) :: key
            character(len=:), allocatable :: message
            message = st%message
            call occ%error_at(key, message, st)
        end subroutine relocate
    end subroutine read_initial_state

    ! DEFI_MATERIAU keeps DIS_CONTACT/COULOMB as data; a contact law on a cell whose material
    ! has friction is what parasol does not build (frictionless DIS_CHOC, DIS_CONTACT).
    subroutine refuse_friction(occ, s, cells, st)
        type(keyword_set_t), intent(in) :: occ
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: cells(:)
        type(status_t), intent(out) :: st
        integer(i4) :: k, m
        if (.not. allocated(s%materials%cell_material)) return
        do k = 1, size(cells)
            m = s%materials%cell_material(cells(k))
            if (m <= 0) cycle
            associate (mat => s%materials%materials(m))
                if (.not. mat%has_dis_contact) cycle
                if (.not. abs(mat%dis_contact%coulomb) > 0.0_dp) cycle
                call occ%error_at('RELATION', 'the material of cell ' // &
                    cell_name(s%mesh, cells(k)) // ' has DIS_CONTACT COULOMB = ' // &
                    real_e13(mat%dis_contact%coulomb) // ': friction is not built yet ' // &
                    '(parasol has frictionless DIS_CHOC and DIS_CONTACT)', st, &
                    code=STATUS_NOT_IMPLEMENTED)
                return
            end associate
        end do
    end subroutine refuse_friction

    !> INCREMENT: LIST_INST (a DEFI_LIST_REEL, or a DEFI_LIST_INST with what a failed step
    !> does: time_stepping) restricted to [INST_INIT, INST_FIN] (NUME_INST_INIT/FIN: indices
    !> from 0). times(1) is the initial instant: without INST_INIT and NUME_INST_INIT, the
    !> instant of the initial state t_state when there is one (ETAT_INIT), which must then be
    !> an instant of the list, else the list's first.
    !>  cutting : out, the list's ECHEC policy (off for a DEFI_LIST_REEL)
    !>  st      : out, located at INCREMENT/LIST_INST: an empty selection; what the
    !>            DEFI_LIST_INST asks for that parasol does not build
    subroutine read_increment(cmd, times, cutting, st, t_state)
        type(command_t), intent(in) :: cmd
        real(dp), allocatable, intent(out) :: times(:)
        type(step_cutting_t), intent(out) :: cutting
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: t_state
        type(keyword_set_t) :: occ
        class(concept_t), pointer :: p
        real(dp) :: t0, t1
        integer(i4) :: i0, i1
        occ = cmd%occurrence('INCREMENT', 1)
        call occ%get_concept('LIST_INST', p, st)
        if (st%failed()) return
        select type (p)
        type is (real_list_t)
            times = p%values
        type is (list_inst_concept_t)
            times = p%instants
            call step_cutting_for(p, cutting, st)
            if (st%failed()) then
                call occ%error_at('LIST_INST', st%message, st, code=STATUS_NOT_IMPLEMENTED)
                return
            end if
        class default
            call occ%error_at('LIST_INST', 'expected a list of instants (DEFI_LIST_REEL, ' // &
                'DEFI_LIST_INST)', st)
            return
        end select
        i0 = 1
        i1 = size(times, kind=i4)
        if (occ%has('NUME_INST_INIT')) call occ%get_int('NUME_INST_INIT', i0, st)
        if (occ%has('NUME_INST_INIT')) i0 = i0 + 1
        if (occ%has('NUME_INST_FIN')) call occ%get_int('NUME_INST_FIN', i1, st)
        if (occ%has('NUME_INST_FIN')) i1 = i1 + 1
        if (occ%has('INST_INIT')) then
            call occ%get_real('INST_INIT', t0, st)
            i0 = instant_index(times, t0)
        else if (present(t_state) .and. .not. occ%has('NUME_INST_INIT')) then
            i0 = instant_index(times, t_state)
            if (i0 == 0) then
                call occ%error_at('LIST_INST', 'the instant of the initial state (ETAT_INIT), '&
                    // real_e13(t_state) // ', is not in the list: give INST_INIT', st, &
                    code=STATUS_MODEL_ERROR)
                return
            end if
        end if
        if (occ%has('INST_FIN')) then
            call occ%get_real('INST_FIN', t1, st)
            i1 = instant_index(times, t1)
        end if
        if (st%failed()) return
        if (i0 < 1 .or. i1 > size(times) .or. i1 <= i0) then
            call occ%error_at('LIST_INST', 'the increment selects no step of the list ' // &
                '(initial index ' // to_text(i0 - 1) // ', final ' // to_text(i1 - 1) // &
                ', list of ' // to_text(size(times)) // ' instants)', st, &
                code=STATUS_MODEL_ERROR)
            return
        end if
        times = times(i0:i1)
    end subroutine read_increment

    !> Index of instant t in the list (relative precision RESULT_INST_PRECISION), 0 if none.
    pure integer(i4) function instant_index(times, t) result(k)
        real(dp), intent(in) :: times(:), t
        do k = 1, size(times, kind=i4)
            if (abs(times(k) - t) <= RESULT_INST_PRECISION * max(abs(t), 1.0_dp)) return
        end do
        k = 0
    end function instant_index

    !> NEWTON, CONVERGENCE, SOLVEUR.
    subroutine read_newton(ctx, cmd, options, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(newton_options_t), intent(out) :: options
        type(status_t), intent(out) :: st
        type(keyword_set_t) :: occ
        character(len=:), allocatable :: text
        if (cmd%count('NEWTON') > 0) then
            occ = cmd%occurrence('NEWTON', 1)
            options%prediction_given = occ%has('PREDICTION')
            if (options%prediction_given) then
                call occ%get_text('PREDICTION', text, st)
                options%prediction_elastic = text == 'ELASTIQUE'
            end if
            call occ%get_text('MATRICE', text, st)
            options%matrix_elastic = text == 'ELASTIQUE'
            if (st%ok()) call occ%get_int('REAC_ITER', options%reac_iter, st)
            if (st%ok()) call occ%get_int('REAC_INCR', options%reac_incr, st)
            if (st%failed()) return
        end if
        if (cmd%count('RECH_LINEAIRE') > 0) then
            call read_line_search(cmd%occurrence('RECH_LINEAIRE', 1), options%line, st)
            if (st%failed()) return
        end if
        if (cmd%count('CONVERGENCE') > 0) then
            ! Code_Aster (U4.51.03, nmcore): the criteria given are all tested; RESI_GLOB_RELA
            ! at its default 1e-6 only when neither is given.
            occ = cmd%occurrence('CONVERGENCE', 1)
            options%use_maxi = occ%has('RESI_GLOB_MAXI')
            options%use_rela = occ%has('RESI_GLOB_RELA') .or. .not. options%use_maxi
            if (options%use_maxi) call occ%get_real('RESI_GLOB_MAXI', options%resi_glob_maxi, &
                st)
            if (st%ok() .and. occ%has('RESI_GLOB_RELA')) call occ%get_real('RESI_GLOB_RELA', &
                options%resi_glob_rela, st)
            if (st%failed()) return
            if (options%use_rela .and. .not. options%resi_glob_rela > 0.0_dp) then
                call occ%error_at('RESI_GLOB_RELA', 'must be > 0 (got ' // &
                    real_e13(options%resi_glob_rela) // ')', st, code=STATUS_MODEL_ERROR)
                return
            end if
            if (options%use_maxi .and. .not. options%resi_glob_maxi > 0.0_dp) then
                call occ%error_at('RESI_GLOB_MAXI', 'must be > 0 (got ' // &
                    real_e13(options%resi_glob_maxi) // ')', st, code=STATUS_MODEL_ERROR)
                return
            end if
            if (st%ok()) call occ%get_int('ITER_GLOB_MAXI', options%iter_glob_maxi, st)
            if (st%failed()) return
        end if
        options%factor%method = DEFAULT_METHOD
        options%factor%renum = default_renum(DEFAULT_METHOD)
        if (cmd%count('SOLVEUR') == 0) return
        occ = cmd%occurrence('SOLVEUR', 1)
        call read_solver(ctx, occ, options%factor, st)
    end subroutine read_newton

    !> SOLVEUR (U4.50.01): METHODE (default MUMPS, as Code_Aster), RENUM (checked against
    !> the method, solver_factory), NPREC (kept as given: its meaning depends on the method,
    !> direct_solver), STOP_SINGULIER, ACCELERATION (MUMPS: parasol always factors in full
    !> rank, i.e. 'FR'; another value is noted in the .mess).
    !>  st : out, located at RENUM when the method has no such ordering
    subroutine read_solver(ctx, occ, solver, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(solver_options_t), intent(inout) :: solver
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: text
        call occ%get_text('METHODE', text, st)
        if (st%failed()) return
        solver%method = text
        solver%renum = default_renum(text)
        if (occ%has('RENUM')) then
            call occ%get_text('RENUM', text, st)
            if (st%failed()) return
            if (index(' ' // renum_allowed(trim(solver%method)) // ' ', ' ' // text // ' ') &
                == 0) then
                call occ%error_at('RENUM', text // ' is not an ordering of METHODE=''' // &
                    trim(solver%method) // ''' (' // renum_allowed(trim(solver%method)) // &
                    '; default ' // default_renum(trim(solver%method)) // ')', st)
                return
            end if
            solver%renum = text
        end if
        if (text == 'GCPC' .or. text == 'PETSC') call read_iterative(occ, solver, st)
        if (st%failed()) return
        call occ%get_int('NPREC', solver%nprec, st)
        if (st%ok()) call occ%get_text('STOP_SINGULIER', text, st)
        if (st%failed()) return
        solver%stop_singular = text == 'OUI'
        if (occ%has('ACCELERATION')) then
            call occ%get_text('ACCELERATION', text, st)
            if (st%failed()) return
            if (text /= 'FR' .and. text /= 'AUTO') call ctx%write_mess('    SOLVEUR/' // &
                'ACCELERATION ' // text // ': parasol factors in full rank (FR)')
        end if
    end subroutine read_solver

    !> SOLVEUR of METHODE GCPC / PETSC (krylov_solver): PRE_COND, ALGORITHME, RESI_RELA,
    !> NMAX_ITER as Code_Aster documents them (U4.50.01; defaults from the catalog). What
    !> parasol does not build is refused at its keyword: it is never replaced by another.
    !>  st : out, located at PRE_COND, ALGORITHME, NIVE_REMPLISSAGE, OPTION_PETSC, RESI_RELA
    subroutine read_iterative(occ, solver, st)
        type(keyword_set_t), intent(in) :: occ
        type(solver_options_t), intent(inout) :: solver
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: text
        integer(i4) :: level
        call occ%get_text('PRE_COND', text, st)
        if (st%failed()) return
        if (index(' ' // pre_cond_allowed(trim(solver%method)) // ' ', ' ' // text // ' ') &
            == 0) then
            call occ%error_at('PRE_COND', text // ' is not built by parasol (preconditioners ' &
                // 'of METHODE=''' // trim(solver%method) // ''': ' // &
                pre_cond_allowed(trim(solver%method)) // ')', st, code=STATUS_NOT_IMPLEMENTED)
            return
        end if
        solver%pre_cond = text
        solver%algorithm = 'CG'
        if (trim(solver%method) == 'PETSC') then
            call occ%get_text('ALGORITHME', text, st)
            if (st%failed()) return
            if (index(' ' // algorithm_allowed('PETSC') // ' ', ' ' // text // ' ') == 0) then
                call occ%error_at('ALGORITHME', text // ' is not built by parasol (Krylov ' // &
                    'methods of METHODE=''PETSC'': ' // algorithm_allowed('PETSC') // ')', st, &
                    code=STATUS_NOT_IMPLEMENTED)
                return
            end if
            solver%algorithm = text
            if (occ%has('OPTION_PETSC')) then
                call occ%get_text('OPTION_PETSC', text, st)
                if (st%failed()) return
                if (len_trim(text) > 0) then
                    call occ%error_at('OPTION_PETSC', 'PETSc''s command-line options are ' // &
                        'not read by parasol (its own Krylov methods): use ALGORITHME, ' // &
                        'PRE_COND, RESI_RELA, NMAX_ITER', st, code=STATUS_NOT_IMPLEMENTED)
                    return
                end if
            end if
        end if
        call occ%get_int('NIVE_REMPLISSAGE', level, st)
        if (st%failed()) return
        if (level /= 0 .and. solver%pre_cond == 'LDLT_INC') then
            call occ%error_at('NIVE_REMPLISSAGE', 'parasol builds the incomplete ' // &
                'factorization without fill (NIVE_REMPLISSAGE=0) only', st, &
                code=STATUS_NOT_IMPLEMENTED)
            return
        end if
        call occ%get_int('NMAX_ITER', solver%nmax_iter, st)
        if (st%failed()) return
        solver%resi_rela = KRYLOV_DEFAULT_RESI_RELA
        if (occ%has('RESI_RELA')) then
            call occ%get_real('RESI_RELA', solver%resi_rela, st)
            if (st%failed()) return
            if (.not. (solver%resi_rela > 0.0_dp .and. solver%resi_rela < 1.0_dp)) then
                call occ%error_at('RESI_RELA', 'the relative residual of an iterative ' // &
                    'METHODE must be in (0, 1) (default 1e-6)', st)
                return
            end if
        end if
    end subroutine read_iterative

    !> RECH_LINEAIRE (U4.51.03; residual_line_search): METHODE CORDE or MIXTE (PILOTAGE goes
    !> with PILOTAGE, which parasol does not build), RESI_LINE_RELA, ITER_LINE_MAXI (0: no
    !> search), RHO_MIN < RHO_MAX, RHO_EXCL.
    !>  st : out, located at METHODE (PILOTAGE) or RHO_MAX (not above RHO_MIN)
    subroutine read_line_search(occ, line, st)
        type(keyword_set_t), intent(in) :: occ
        type(line_search_options_t), intent(inout) :: line
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: text
        call occ%get_text('METHODE', text, st)
        if (st%failed()) return
        if (text == 'PILOTAGE') then
            call occ%error_at('METHODE', 'the line search PILOTAGE goes with STAT_NON_LINE/' // &
                'PILOTAGE (continuation), which parasol does not build: use CORDE or MIXTE', &
                st, code=STATUS_NOT_IMPLEMENTED)
            return
        end if
        line%mixte = text == 'MIXTE'
        call occ%get_real('RESI_LINE_RELA', line%resi_line_rela, st)
        if (st%ok()) call occ%get_int('ITER_LINE_MAXI', line%iter_line_maxi, st)
        if (st%ok()) call occ%get_real('RHO_MIN', line%rho_min, st)
        if (st%ok()) call occ%get_real('RHO_MAX', line%rho_max, st)
        if (st%ok()) call occ%get_real('RHO_EXCL', line%rho_excl, st)
        if (st%failed()) return
        if (.not. line%rho_max > line%rho_min) then
            call occ%error_at('RHO_MAX', 'must be above RHO_MIN (' // real_e13(line%rho_min) // &
                '): the steps of the line search lie in [RHO_MIN, RHO_MAX]', st, &
                code=STATUS_MODEL_ERROR)
            return
        end if
        line%enabled = line%iter_line_maxi > 0
    end subroutine read_line_search

end module analysis_commands
