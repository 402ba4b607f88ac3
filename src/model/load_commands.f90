!> Command handlers AFFE_CHAR_MECA (real values) and AFFE_CHAR_MECA_F (function values):
!> a char_meca concept holding a load_set_t (model_loads) and the model it was made on;
!> AFFE_CHAR_CINE / AFFE_CHAR_CINE_F (MECA_IMPO): the same concept typed char_cine_meca,
!> whose load set is kinematic (imposed values eliminated, Code_Aster U4.44.03).
!> Function values point at function concepts owned by the run context (model_loads).
module load_commands
    use kinds, only: dp, i4
    use status, only: status_t, STATUS_MODEL_ERROR
    use strings, only: string_t, to_text
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t, concept_ref_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, find_node_group, find_node, nodes_of_group, nodes_of_cells, &
        node_name
    use model_dof_numbering, only: COMPONENT_NAMES
    use mesh_command_support, only: relocate_error, group_cells, all_cells, warn_at
    use model_types, only: is_plate, is_plane_edge, is_plate_edge, is_plane_solid
    use model_concept, only: model_concept_t
    use model_loads, only: load_set_t, load_add_item, load_set_constant, load_set_function, &
        LOAD_DDL_IMPO, LOAD_FORCE_NODALE, LOAD_FORCE_COQUE, LOAD_PRES_REP, &
        LOAD_FORCE_CONTOUR, LOAD_FORCE_ARETE, LOAD_FORCE_INTERNE, LOAD_PESANTEUR, &
        SLOT_ANGLES, PLAN_SUP, PLAN_INF, PLAN_MOY, load_set_location, LOAD_PRE_EPSI, &
        LOAD_PRE_EPSI_PLATE
    use function_concept, only: function_concept_t
    use force_coque_fo, only: force_coque_fo_pressures
    use relation_commands, only: select_nodes, face_impo_item, liaison_ddl_item, &
        liaison_oblique_item, liaison_unif_item, liaison_solide_item, liaison_rbe3_item, &
        liaison_group_item
    use relation_mail, only: liaison_mail_item
    use relation_proj, only: liaison_proj_item
    use load_occurrences, only: locate_item
    implicit none
    private

    !> The char_meca concept.
    type, extends(concept_t), public :: char_meca_concept_t
        type(load_set_t) :: loads
        class(concept_t), pointer :: model => null()   !< MODELE (owned by the run context)
        logical :: kinematic = .false.                 !< AFFE_CHAR_CINE(_F): char_cine_meca
    contains
        procedure :: type_name => char_meca_type_name
        procedure :: summary => char_meca_summary
    end type char_meca_concept_t

    public :: run_affe_char_meca, run_affe_char_meca_f, run_affe_char_cine, run_affe_char_cine_f

    !> The value keywords of FORCE_COQUE and PRES_REP by slot (model_loads; '_': none).
    character(len=4), parameter :: FORCE_COQUE_KEYS(7) = ['FX  ', 'FY  ', 'FZ  ', 'MX  ', &
        'MY  ', 'MZ  ', 'PRES']
    character(len=4), parameter :: FORCE_COQUE_FO_KEYS(7) = ['_   ', '_   ', '_   ', &
        '_   ', '_   ', '_   ', 'PRES']
    character(len=4), parameter :: FORCE_COQUE_LOCAL_KEYS(5) = ['F1  ', 'F2  ', 'F3  ', &
        'MF1 ', 'MF2 ']
    character(len=7), parameter :: PRES_REP_KEYS(8) = ['_      ', '_      ', '_      ', &
        '_      ', '_      ', '_      ', 'PRES   ', 'CISA_2D']

contains

    function char_meca_type_name(self) result(name)
        class(char_meca_concept_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'char_meca'
        if (self%kinematic) name = 'char_cine_meca'
    end function char_meca_type_name

    function char_meca_summary(self) result(text)
        class(char_meca_concept_t), intent(in) :: self
        character(len=:), allocatable :: text
        text = self%type_name() // ' with ' // to_text(self%loads%n_items) // ' load item(s)'
    end function char_meca_summary

    !> AFFE_CHAR_MECA: DDL_IMPO, FORCE_NODALE, FORCE_COQUE, PRES_REP, FORCE_CONTOUR with reals.
    !>  st : out, located at the keyword: unknown group/node, a load on cells of the wrong
    !>       element kind
    subroutine run_affe_char_meca(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        call build_char_meca(ctx, cmd, .false., result, st)
    end subroutine run_affe_char_meca

    !> AFFE_CHAR_MECA_F: the same with functions of (INST, X, Y, Z) as values.
    subroutine run_affe_char_meca_f(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        call build_char_meca(ctx, cmd, .true., result, st)
    end subroutine run_affe_char_meca_f

    !> AFFE_CHAR_CINE: MECA_IMPO = _F(TOUT | GROUP_MA | GROUP_NO | NOEUD, DX..DRZ) with reals,
    !> imposed by elimination (the reactions are f_int - f_ext there, as for DDL_IMPO).
    !>  st : out, located at the keyword: unknown group/node, a component a node lacks
    subroutine run_affe_char_cine(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        call build_char_cine(ctx, cmd, .false., result, st)
    end subroutine run_affe_char_cine

    !> AFFE_CHAR_CINE_F: the same with functions of (INST, X, Y, Z).
    subroutine run_affe_char_cine_f(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        call build_char_cine(ctx, cmd, .true., result, st)
    end subroutine run_affe_char_cine_f

    subroutine build_char_cine(ctx, cmd, functions, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        logical, intent(in) :: functions
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(char_meca_concept_t), allocatable :: cm
        class(concept_t), pointer :: p
        integer(i4) :: i
        call cmd%get_concept('MODELE', p, st)
        if (st%failed()) return
        allocate (cm)
        cm%model => p
        cm%kinematic = .true.
        cm%loads%kinematic = .true.
        select type (p)
        type is (model_concept_t)
            do i = 1, cmd%count('MECA_IMPO')
                call node_item(cmd%occurrence('MECA_IMPO', i), p, LOAD_DDL_IMPO, &
                    ['DX ', 'DY ', 'DZ ', 'DRX', 'DRY', 'DRZ'], functions, cm%loads, st)
                if (st%failed()) return
                call unheld_components(ctx, cmd%occurrence('MECA_IMPO', i), p)
            end do
            if (cmd%has('EVOL_IMPO')) call evol_impo_items(cmd, p, cm%loads, st)
            if (st%failed()) return
        class default
            call cmd%error_at('MODELE', 'expected a model (modele), got ' // p%type_name(), st)
            return
        end select
        call ctx%write_mess('    ' // cm%summary())
        call move_alloc(cm, result)
    end subroutine build_char_cine

    ! AFFE_CHAR_CINE/MECA_IMPO: a component the occurrence's nodes lack is dropped where a
    ! node lacks it, as Code_Aster's charci (a field of every component, read by the
    ! numbering where it has the equation); one no node has imposes nothing: a located
    ! warning says so.
    subroutine unheld_components(ctx, occ, mc)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        integer(i4), allocatable :: nodes(:)
        character(len=:), allocatable :: label
        type(status_t) :: st
        integer(i4) :: comp
        call select_nodes(occ, mc, nodes, label, st)
        if (st%failed()) return
        do comp = 1, size(COMPONENT_NAMES, kind=i4)
            if (.not. occ%has(trim(COMPONENT_NAMES(comp)))) cycle
            if (any(mc%dofs%equation(comp, nodes) /= 0)) cycle
            call warn_at(ctx, occ, trim(COMPONENT_NAMES(comp)), 'none of the ' // &
                to_text(size(nodes, kind=i4)) // ' node(s) has ' // &
                trim(COMPONENT_NAMES(comp)) // ' in the model: it imposes nothing ' // &
                '(Code_Aster drops it)')
        end do
    end subroutine unheld_components

    subroutine build_char_meca(ctx, cmd, functions, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        logical, intent(in) :: functions
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(char_meca_concept_t), allocatable :: cm
        class(concept_t), pointer :: p
        integer(i4) :: i
        call cmd%get_concept('MODELE', p, st)
        if (st%failed()) return
        allocate (cm)
        cm%model => p
        select type (p)
        type is (model_concept_t)
            do i = 1, cmd%count('DDL_IMPO')
                call node_item(cmd%occurrence('DDL_IMPO', i), p, LOAD_DDL_IMPO, &
                    ['DX ', 'DY ', 'DZ ', 'DRX', 'DRY', 'DRZ'], functions, cm%loads, st)
                if (st%failed()) return
            end do
            do i = 1, cmd%count('CHAMNO_IMPO')
                call chamno_impo_item(cmd%occurrence('CHAMNO_IMPO', i), p, cm%loads, st)
                if (st%failed()) return
            end do
            call relation_items(ctx, cmd, p, functions, cm%loads, st)
            if (st%failed()) return
            do i = 1, cmd%count('FORCE_NODALE')
                call node_item(cmd%occurrence('FORCE_NODALE', i), p, LOAD_FORCE_NODALE, &
                    ['FX', 'FY', 'FZ', 'MX', 'MY', 'MZ'], functions, cm%loads, st)
                if (st%failed()) return
            end do
            do i = 1, cmd%count('FORCE_COQUE')
                call cell_item(cmd%occurrence('FORCE_COQUE', i), p, LOAD_FORCE_COQUE, &
                    FORCE_COQUE_KEYS, functions, cm%loads, st)
                if (st%failed()) return
            end do
            ! FORCE_COQUE_FO (AFFE_CHAR_MECA): its PRES is a function of space, evaluated
            ! here once per cell at the cell's centre (force_coque_fo)
            do i = 1, cmd%count('FORCE_COQUE_FO')
                call cell_item(cmd%occurrence('FORCE_COQUE_FO', i), p, LOAD_FORCE_COQUE, &
                    FORCE_COQUE_FO_KEYS, .true., cm%loads, st)
                if (st%ok()) call force_coque_fo_pressures(cmd, &
                    cmd%occurrence('FORCE_COQUE_FO', i), p, cm%loads, cm%loads%n_items, st)
                if (st%failed()) return
            end do
            do i = 1, cmd%count('PRES_REP')
                call cell_item(cmd%occurrence('PRES_REP', i), p, LOAD_PRES_REP, &
                    PRES_REP_KEYS, functions, cm%loads, st)
                if (st%failed()) return
            end do
            do i = 1, cmd%count('FORCE_CONTOUR')
                call cell_item(cmd%occurrence('FORCE_CONTOUR', i), p, LOAD_FORCE_CONTOUR, &
                    ['FX', 'FY', 'FZ'], functions, cm%loads, st)
                if (st%failed()) return
            end do
            do i = 1, cmd%count('PRE_EPSI')
                call pre_epsi_item(cmd%occurrence('PRE_EPSI', i), p, functions, cm%loads, st)
                if (st%failed()) return
            end do
            do i = 1, cmd%count('FORCE_ARETE')
                call cell_item(cmd%occurrence('FORCE_ARETE', i), p, LOAD_FORCE_ARETE, &
                    ['FX', 'FY', 'FZ', 'MX', 'MY', 'MZ'], functions, cm%loads, st)
                if (st%failed()) return
            end do
            do i = 1, cmd%count('FORCE_INTERNE')
                call cell_item(cmd%occurrence('FORCE_INTERNE', i), p, LOAD_FORCE_INTERNE, &
                    ['FX', 'FY', 'FZ'], functions, cm%loads, st)
                if (st%failed()) return
            end do
            if (cmd%count('PESANTEUR') > 0) then
                call pesanteur_item(cmd%occurrence('PESANTEUR', 1), p, cm%loads, st)
                if (st%failed()) return
            end if
        class default
            call cmd%error_at('MODELE', 'expected a model (modele), got ' // p%type_name(), st)
            return
        end select
        call ctx%write_mess('    ' // cm%summary())
        call move_alloc(cm, result)
    end subroutine build_char_meca

    !> FACE_IMPO, ARETE_IMPO and the LIAISON_* keywords (relation_commands, relation_mail,
    !> relation_proj).
    subroutine relation_items(ctx, cmd, mc, functions, loads, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(model_concept_t), intent(in) :: mc
        logical, intent(in) :: functions
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        integer(i4) :: i
        logical, allocatable :: elim(:)
        do i = 1, cmd%count('FACE_IMPO')
            call face_impo_item(cmd%occurrence('FACE_IMPO', i), mc, functions, .false., &
                loads, st)
            if (st%failed()) return
        end do
        do i = 1, cmd%count('ARETE_IMPO')
            call face_impo_item(cmd%occurrence('ARETE_IMPO', i), mc, functions, .true., &
                loads, st)
            if (st%failed()) return
        end do
        do i = 1, cmd%count('LIAISON_DDL')
            call liaison_ddl_item(cmd%occurrence('LIAISON_DDL', i), mc, functions, loads, st)
            if (st%failed()) return
        end do
        do i = 1, cmd%count('LIAISON_OBLIQUE')
            call liaison_oblique_item(cmd%occurrence('LIAISON_OBLIQUE', i), mc, functions, &
                loads, st)
            if (st%failed()) return
        end do
        do i = 1, cmd%count('LIAISON_GROUP')
            call liaison_group_item(cmd%occurrence('LIAISON_GROUP', i), mc, functions, &
                loads, st)
            if (st%failed()) return
        end do
        do i = 1, cmd%count('LIAISON_UNIF')
            call liaison_unif_item(cmd%occurrence('LIAISON_UNIF', i), mc, loads, st)
            if (st%failed()) return
        end do
        do i = 1, cmd%count('LIAISON_SOLIDE')
            call liaison_solide_item(cmd%occurrence('LIAISON_SOLIDE', i), mc, loads, st)
            if (st%failed()) return
        end do
        do i = 1, cmd%count('LIAISON_RBE3')
            call liaison_rbe3_item(cmd%occurrence('LIAISON_RBE3', i), mc, loads, st)
            if (st%failed()) return
        end do
        ! ELIM_MULT: the slave nodes of the earlier LIAISON_MAIL occurrences.
        allocate (elim(mc%mesh%n_nodes), source=.false.)
        do i = 1, cmd%count('LIAISON_MAIL')
            call liaison_mail_item(ctx, cmd%occurrence('LIAISON_MAIL', i), mc, elim, loads, st)
            if (st%failed()) return
        end do
        do i = 1, cmd%count('LIAISON_PROJ')
            call liaison_proj_item(ctx, cmd%occurrence('LIAISON_PROJ', i), mc, loads, st)
            if (st%failed()) return
        end do
    end subroutine relation_items

    !> DDL_IMPO / FORCE_NODALE occurrence: the nodes of TOUT, GROUP_NO, GROUP_MA and NOEUD
    !> less SANS_GROUP_MA and SANS_GROUP_NO (relation_commands select_nodes).
    subroutine node_item(occ, mc, kind, keys, functions, loads, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        integer(i4), intent(in) :: kind
        character(len=*), intent(in) :: keys(:)
        logical, intent(in) :: functions
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: nodes(:)
        integer(i4) :: k, index
        character(len=:), allocatable :: label
        call select_nodes(occ, mc, nodes, label, st)
        if (st%failed()) return
        if (any([(occ%has(trim(keys(k))), k = 1, size(keys))])) then
            call load_add_item(loads, kind, nodes, index, label)
            call locate_item(occ, loads, index)
            do k = 1, size(keys)
                call set_slot(occ, trim(keys(k)), k, index, functions, loads, st)
                if (st%failed()) return
                if (occ%has(trim(keys(k))) .and. .not. loads%kinematic) then
                    call check_component(occ, mc, nodes, trim(keys(k)), k, st)
                    if (st%failed()) return
                end if
            end do
            if (kind == LOAD_FORCE_NODALE .and. occ%has('ANGL_NAUT')) then
                call angle_slots(occ, functions, index, loads, st)
                if (st%failed()) return
            end if
        end if
        if (occ%has('BLOCAGE')) call blocage_item(occ, mc, nodes, label, keys, loads, st)
    end subroutine node_item

    !> FORCE_NODALE/ANGL_NAUT: the 1 to 3 nautical angles (degrees; reals, or functions
    !> of INST, X, Y, Z in AFFE_CHAR_MECA_F) into slots SLOT_ANGLES.. (the missing ones 0):
    !> FX..MZ are then components in that frame (Code_Aster cafono, REP = UTILISAT).
    subroutine angle_slots(occ, functions, index, loads, st)
        type(keyword_set_t), intent(in) :: occ
        logical, intent(in) :: functions
        integer(i4), intent(in) :: index
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        real(dp), allocatable :: angles(:)
        type(concept_ref_t), allocatable :: refs(:)
        integer(i4) :: k
        loads%items(index)%angles = .true.
        do k = 0, 2
            call load_set_constant(loads, index, SLOT_ANGLES + k, 0.0_dp)
        end do
        if (.not. functions) then
            call occ%get_reals('ANGL_NAUT', angles, st)
            if (st%failed()) return
            do k = 1, min(3, size(angles, kind=i4))
                call load_set_constant(loads, index, SLOT_ANGLES + k - 1, angles(k))
            end do
            return
        end if
        call occ%get_concepts('ANGL_NAUT', refs, st)
        if (st%failed()) return
        do k = 1, min(3, size(refs, kind=i4))
            select type (f => refs(k)%ptr)
            class is (function_concept_t)
                call load_set_function(loads, index, SLOT_ANGLES + k - 1, f)
            class default
                call occ%error_at('ANGL_NAUT', 'expected functions (DEFI_CONSTANTE, ' // &
                    'DEFI_FONCTION, FORMULE), got ' // f%type_name(), st)
                return
            end select
        end do
    end subroutine angle_slots

    !> DDL_IMPO/BLOCAGE = 'DEPLACEMENT' (DX DY DZ) and/or 'ROTATION' (DRX DRY DRZ): 0 on the
    !> components each node has, skipping the others (Code_Aster caddli). A component also
    !> given by value in the occurrence, or a BLOCAGE that blocks nothing on any node, is an
    !> error at BLOCAGE.
    subroutine blocage_item(occ, mc, nodes, label, keys, loads, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        integer(i4), intent(in) :: nodes(:)
        character(len=*), intent(in) :: label, keys(:)
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: kinds(:)
        logical :: blocked(6)
        integer(i4) :: k, comp, index
        call occ%get_texts('BLOCAGE', kinds, st)
        if (st%failed()) return
        blocked = .false.
        do k = 1, size(kinds)
            if (kinds(k)%s == 'DEPLACEMENT') blocked(1:3) = .true.
            if (kinds(k)%s == 'ROTATION') blocked(4:6) = .true.
        end do
        do comp = 1, 6
            if (blocked(comp) .and. occ%has(trim(keys(comp)))) then
                call occ%error_at('BLOCAGE', trim(keys(comp)) // ' is given a value and ' // &
                    'blocked by BLOCAGE as well: give it one or the other', st, &
                    code=STATUS_MODEL_ERROR)
                return
            end if
        end do
        if (.not. any(spread(blocked, 2, size(nodes)) .and. &
                      mc%dofs%equation(:, nodes) /= 0)) then
            call occ%error_at('BLOCAGE', 'blocks nothing: none of the ' // &
                to_text(size(nodes, kind=i4)) // ' node(s) has such a component in the ' // &
                'model', st, code=STATUS_MODEL_ERROR)
            return
        end if
        call load_add_item(loads, LOAD_DDL_IMPO, nodes, index, label)
        call locate_item(occ, loads, index)
        loads%items(index)%blocage = .true.
        do comp = 1, 6
            if (blocked(comp)) call load_set_constant(loads, index, comp, 0.0_dp)
        end do
    end subroutine blocage_item

    !> AFFE_CHAR_CINE EVOL_IMPO (Code_Aster U4.44.03): at every node where the result's DEPL
    !> has values, each component (those of NOM_CMP, default all DX .. DRZ it has) imposed
    !> at its value interpolated in time at each instant of the analysis (model_loads
    !> evol_value). The result must store DEPL at every instant (PROJ_CHAMP's and
    !> CREA_RESU's results do); a component a node lacks in the model is an error.
    subroutine evol_impo_items(cmd, mc, loads, st)
        use field_types, only: FIELD_NOEU, field_component
        use result_fields, only: result_fields_t, result_field_index
        type(command_t), intent(in) :: cmd
        type(model_concept_t), intent(in) :: mc
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        type(string_t), allocatable :: names(:)
        logical :: wanted(6)
        integer(i4) :: k, f, n, comp, i, index, n_nodes
        character(len=:), allocatable :: file
        integer :: line, col
        call cmd%get_concept('EVOL_IMPO', p, st)
        if (st%failed()) return
        call cmd%location('EVOL_IMPO', file, line, col)
        wanted = .true.
        if (cmd%has('NOM_CMP')) then
            call cmd%get_texts('NOM_CMP', names, st)
            if (st%failed()) return
            wanted = .false.
            do k = 1, size(names)
                do comp = 1, 6
                    if (names(k)%s == trim(COMPONENT_NAMES(comp))) wanted(comp) = .true.
                end do
            end do
        end if
        select type (p)
        class is (result_fields_t)
            if (p%n_stored == 0) then
                call cmd%error_at('EVOL_IMPO', 'the result stores no instant', st, &
                    code=STATUS_MODEL_ERROR)
                return
            end if
            do k = 1, p%n_stored
                f = result_field_index(p, k, 'DEPL')
                if (f == 0) then
                    call cmd%error_at('EVOL_IMPO', 'EVOL_IMPO reads DEPL stored in the ' // &
                        'result at every instant (as PROJ_CHAMP and CREA_RESU store it); ' // &
                        p%name // ' has none at INST ' // to_text(p%inst(k)), st, &
                        code=STATUS_MODEL_ERROR)
                    return
                end if
            end do
            f = result_field_index(p, 1_i4, 'DEPL')
            associate (fd => p%stored(1)%items(f)%field)
                if (fd%location /= FIELD_NOEU .or. fd%n_nodes /= mc%mesh%n_nodes) then
                    call cmd%error_at('EVOL_IMPO', 'the result''s DEPL is not a nodal field ' // &
                        'of the model''s mesh', st, code=STATUS_MODEL_ERROR)
                    return
                end if
                n_nodes = 0
                do n = 1, fd%n_nodes
                    if (.not. any(fd%node_has(:, n))) cycle
                    call load_add_item(loads, LOAD_DDL_IMPO, [n], index, 'EVOL_IMPO')
                    call load_set_location(loads, index, file, line, col, cmd%command, &
                        'EVOL_IMPO')
                    do comp = 1, 6
                        if (.not. wanted(comp)) cycle
                        i = field_component(fd, trim(COMPONENT_NAMES(comp)))
                        if (i == 0) cycle
                        if (.not. fd%node_has(i, n)) cycle
                        call check_component(cmd%keyword_set_t, mc, [n], 'EVOL_IMPO', comp, st)
                        if (st%failed()) return
                        loads%items(index)%values(comp)%given = .true.
                        loads%items(index)%values(comp)%evol => p
                        loads%items(index)%values(comp)%evol_node = n
                        loads%items(index)%values(comp)%evol_cmp = COMPONENT_NAMES(comp)
                    end do
                    n_nodes = n_nodes + 1
                end do
                if (n_nodes == 0) call cmd%error_at('EVOL_IMPO', 'the result''s DEPL has ' // &
                    'no value at any node: it imposes nothing', st, code=STATUS_MODEL_ERROR)
            end associate
        class default
            call cmd%error_at('EVOL_IMPO', 'expected a result, got ' // p%type_name(), st)
        end select
    end subroutine evol_impo_items

    !> CHAMNO_IMPO (Code_Aster U4.44.01): every component DX..DRZ a node of the CHAM_NO
    !> carries is imposed at COEF_IMPO times its value, as a DDL_IMPO of that node (Code_Aster
    !> writes it as one linear relation per value; the solution is the same). A value on a
    !> component the node lacks in the model is an error, as for DDL_IMPO.
    subroutine chamno_impo_item(occ, mc, loads, st)
        use field_types, only: FIELD_NOEU, field_component
        use field_concept, only: field_concept_t
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        real(dp) :: coef
        integer(i4) :: n, comp, i, index, n_imposed
        integer(i4) :: at(6)
        call occ%get_concept('CHAM_NO', p, st)
        if (st%ok()) call occ%get_real('COEF_IMPO', coef, st)
        if (st%failed()) return
        select type (p)
        type is (field_concept_t)
            associate (f => p%field)
                if (f%location /= FIELD_NOEU .or. f%n_nodes /= mc%mesh%n_nodes) then
                    call occ%error_at('CHAM_NO', 'expected a nodal field of the model''s ' // &
                        'mesh (' // to_text(mc%mesh%n_nodes) // ' nodes), got a field of ' // &
                        to_text(merge(f%n_nodes, f%n_cells, f%location == FIELD_NOEU)) // &
                        ' ' // trim(merge('nodes', 'cells', f%location == FIELD_NOEU)), st, &
                        code=STATUS_MODEL_ERROR)
                    return
                end if
                do comp = 1, 6
                    at(comp) = field_component(f, trim(COMPONENT_NAMES(comp)))
                end do
                if (all(at == 0)) then
                    call occ%error_at('CHAM_NO', 'the field has none of the components ' // &
                        'DX DY DZ DRX DRY DRZ (it is a ' // f%quantity // ')', st, &
                        code=STATUS_MODEL_ERROR)
                    return
                end if
                n_imposed = 0
                do n = 1, f%n_nodes
                    if (.not. any([(at(comp) > 0, comp = 1, 6)])) cycle
                    if (.not. any([(f%node_has(max(at(comp), 1), n) .and. at(comp) > 0, &
                        comp = 1, 6)])) cycle
                    call load_add_item(loads, LOAD_DDL_IMPO, [n], index, 'CHAMNO_IMPO')
                    call locate_item(occ, loads, index)
                    do comp = 1, 6
                        i = at(comp)
                        if (i == 0) cycle
                        if (.not. f%node_has(i, n)) cycle
                        call check_component(occ, mc, [n], 'CHAM_NO', comp, st)
                        if (st%failed()) return
                        call load_set_constant(loads, index, comp, coef * f%node_values(i, n))
                    end do
                    n_imposed = n_imposed + 1
                end do
                if (n_imposed == 0) call occ%error_at('CHAM_NO', 'the field has no value ' // &
                    'at any node: it imposes nothing', st, code=STATUS_MODEL_ERROR)
            end associate
        class default
            call occ%error_at('CHAM_NO', 'expected a nodal field (cham_no_sdaster), got ' // &
                p%type_name(), st)
        end select
    end subroutine chamno_impo_item

    !> A DDL_IMPO or FORCE_NODALE value on a component a node does not have (its elements do
    !> not use it) is an error at the keyword: it would silently do nothing.
    !>  comp : the component (DOF_DX..DOF_DRZ) of the keyword: DX or FX = 1, ..., DRZ or MZ = 6
    subroutine check_component(occ, mc, nodes, key, comp, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        integer(i4), intent(in) :: nodes(:)
        character(len=*), intent(in) :: key
        integer(i4), intent(in) :: comp
        type(status_t), intent(out) :: st
        integer(i4) :: k, c
        character(len=:), allocatable :: has
        do k = 1, size(nodes)
            if (mc%dofs%equation(comp, nodes(k)) /= 0) cycle
            has = ''
            do c = 1, size(COMPONENT_NAMES)
                if (mc%dofs%equation(c, nodes(k)) /= 0) has = has // ' ' // trim(COMPONENT_NAMES(c))
            end do
            if (len(has) == 0) has = ' none'
            call occ%error_at(key, 'node ' // node_name(mc%mesh, nodes(k)) // &
                ' has no component ' // trim(COMPONENT_NAMES(comp)) // ' in the model (its ' // &
                'elements give it:' // has // '); remove ' // key // &
                ' or model the node with an element that has it', st)
            return
        end do
    end subroutine check_component

    !> A cell load occurrence (FORCE_COQUE, PRES_REP, FORCE_CONTOUR, FORCE_ARETE,
    !> FORCE_INTERNE): cells from GROUP_MA, or TOUT (the model's cells the load fits), of the
    !> element kinds the load needs (load_fits); keys(k) is read into slot k.
    !>  st : out, located: a cell the load does not fit, a value the cells cannot carry
    subroutine cell_item(occ, mc, kind, keys, functions, loads, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        integer(i4), intent(in) :: kind
        character(len=*), intent(in) :: keys(:)
        logical, intent(in) :: functions
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: cells(:)
        integer(i4) :: k, index
        logical, allocatable :: fits(:)
        type(string_t), allocatable :: plan(:)
        if (occ%has('GROUP_MA')) then
            call group_cells(occ, 'GROUP_MA', mc%mesh, cells, st)
            if (st%failed()) return
        else
            cells = all_cells(mc%mesh)
        end if
        fits = load_fits(kind, mc%model%element(cells))
        if (.not. occ%has('GROUP_MA')) cells = pack(cells, fits)
        if (.not. all(fits) .and. occ%has('GROUP_MA') .or. size(cells) == 0) then
            call occ%error_at(merge('GROUP_MA', 'TOUT    ', occ%has('GROUP_MA')), &
                'the load needs ' // fitting_cells(kind) // '; ' // &
                to_text(count(.not. fits)) // ' cell(s) of ' // to_text(size(fits)) // &
                ' do not fit', st, code=STATUS_MODEL_ERROR)
            return
        end if
        call value_checks(occ, mc, kind, cells, st)
        if (st%failed()) return
        call load_add_item(loads, kind, cells, index)
        call locate_item(occ, loads, index)
        do k = 1, size(keys)
            if (keys(k)(1:1) == '_') cycle
            call set_slot(occ, trim(keys(k)), k, index, functions, loads, st)
            if (st%failed()) return
        end do
        if (kind /= LOAD_FORCE_COQUE) return
        ! F1, F2, F3, MF1, MF2: slots 1..5 in the plate's user frame
        do k = 1, size(FORCE_COQUE_LOCAL_KEYS)
            if (.not. occ%has(trim(FORCE_COQUE_LOCAL_KEYS(k)))) cycle
            loads%items(index)%local_frame = .true.
            call set_slot(occ, trim(FORCE_COQUE_LOCAL_KEYS(k)), k, index, functions, loads, st)
            if (st%failed()) return
        end do
        if (loads%items(index)%local_frame) &
            loads%items(index)%slot_names(1:5) = FORCE_COQUE_LOCAL_KEYS
        if (occ%has('PLAN')) then
            call occ%get_texts('PLAN', plan, st)
            if (st%failed()) return
            select case (plan(1)%s)
            case ('SUP')
                loads%items(index)%plan = PLAN_SUP
            case ('INF')
                loads%items(index)%plan = PLAN_INF
            case ('MOY')
                loads%items(index)%plan = PLAN_MOY
            end select
        end if
    end subroutine cell_item

    !> PRE_EPSI occurrence: EPXX .. EPXY on plane cells or EXX .. KXY on plate cells (both in
    !> one occurrence refused: each element reads its own).
    subroutine pre_epsi_item(occ, mc, functions, loads, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        logical, intent(in) :: functions
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        character(len=4), parameter :: PLANE(4) = ['EPXX', 'EPYY', 'EPZZ', 'EPXY']
        character(len=3), parameter :: PLATE(6) = ['EXX', 'EYY', 'EXY', 'KXX', 'KYY', 'KXY']
        integer(i4) :: k
        if (any([(occ%has(trim(PLANE(k))), k = 1, 4)])) then
            do k = 1, 6
                if (occ%has(PLATE(k))) then
                    call occ%error_at(PLATE(k), 'plate strains (EXX .. KXY) and plane ' // &
                        'ones (EPXX .. EPXY) in one occurrence: give each its own, on its ' // &
                        'cells', st, code=STATUS_MODEL_ERROR)
                    return
                end if
            end do
            call cell_item(occ, mc, LOAD_PRE_EPSI, PLANE, functions, loads, st)
        else
            call cell_item(occ, mc, LOAD_PRE_EPSI_PLATE, PLATE, functions, loads, st)
        end if
    end subroutine pre_epsi_item

    !> The cells a load of `kind` applies to, by element kind.
    elemental logical function load_fits(kind, element)
        integer(i4), intent(in) :: kind, element
        select case (kind)
        case (LOAD_FORCE_CONTOUR)
            load_fits = is_plane_edge(element)
        case (LOAD_PRES_REP)
            load_fits = is_plate(element) .or. is_plane_edge(element)
        case (LOAD_FORCE_ARETE)
            load_fits = is_plate_edge(element)
        case (LOAD_FORCE_INTERNE, LOAD_PRE_EPSI)
            load_fits = is_plane_solid(element)
        case default
            load_fits = is_plate(element)
        end select
    end function load_fits

    ! The cells a load kind needs, for messages.
    function fitting_cells(kind) result(text)
        integer(i4), intent(in) :: kind
        character(len=:), allocatable :: text
        select case (kind)
        case (LOAD_FORCE_CONTOUR)
            text = 'SEG2/SEG3 edges of a D_PLAN/C_PLAN model'
        case (LOAD_PRES_REP)
            text = 'plate (DKT) cells or SEG2/SEG3 edges of a D_PLAN/C_PLAN model'
        case (LOAD_FORCE_ARETE)
            text = 'SEG2 edges of a DKT model (the plates'' boundary)'
        case (LOAD_FORCE_INTERNE)
            text = 'D_PLAN/C_PLAN surface cells (TRIA3 .. QUAD9)'
        case (LOAD_PRE_EPSI)
            text = 'D_PLAN/C_PLAN cells for EPXX .. EPXY (plates take EXX .. KXY)'
        case (LOAD_PRE_EPSI_PLATE)
            text = 'plate (DKT) cells for EXX .. KXY (plane elements take EPXX .. EPXY)'
        case default
            text = 'plate (DKT) cells'
        end select
    end function fitting_cells

    ! Values the cells cannot carry: FZ on plane edges and solids (no DZ), CISA_2D on
    ! plates (a plane edge's shear).
    subroutine value_checks(occ, mc, kind, cells, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        integer(i4), intent(in) :: kind, cells(:)
        type(status_t), intent(out) :: st
        if ((kind == LOAD_FORCE_CONTOUR .or. kind == LOAD_FORCE_INTERNE) .and. &
            occ%has('FZ')) then
            call occ%error_at('FZ', 'a D_PLAN/C_PLAN model has no DZ: FZ applies to ' // &
                'AXIS_FOURIER or 3D models, which parasol does not build', st, &
                code=STATUS_MODEL_ERROR)
        else if (kind == LOAD_PRES_REP .and. occ%has('CISA_2D') .and. &
                 any(is_plate(mc%model%element(cells)))) then
            call occ%error_at('CISA_2D', 'CISA_2D is the shear on the edges of a 2D model, ' &
                // 'not on plate (DKT) cells', st, code=STATUS_MODEL_ERROR)
        end if
    end subroutine value_checks

    !> PESANTEUR = _F(GRAVITE=g, DIRECTION=d, GROUP_MA): the force rho g d/|d| per unit
    !> volume on the cells (GROUP_MA, else all: those without a mass take none), as
    !> Code_Aster's capesa (DIRECTION normalised; a zero one refused, CHARGES2_53).
    subroutine pesanteur_item(occ, mc, loads, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: cells(:)
        real(dp), allocatable :: direction(:)
        real(dp) :: g, length
        integer(i4) :: k, index
        call occ%get_real('GRAVITE', g, st)
        if (st%ok()) call occ%get_reals('DIRECTION', direction, st)
        if (st%failed()) return
        length = norm2(direction)
        if (.not. length > tiny(1.0_dp)) then
            call occ%error_at('DIRECTION', 'the direction of gravity is zero (Code_Aster ' // &
                'CHARGES2_53)', st, code=STATUS_MODEL_ERROR)
            return
        end if
        if (occ%has('GROUP_MA')) then
            call group_cells(occ, 'GROUP_MA', mc%mesh, cells, st)
            if (st%failed()) return
        else
            cells = all_cells(mc%mesh)
        end if
        call load_add_item(loads, LOAD_PESANTEUR, cells, index)
        call locate_item(occ, loads, index)
        do k = 1, 3
            call load_set_constant(loads, index, k, g * (direction(k) / length))
        end do
    end subroutine pesanteur_item

    !> Reads keyword `key` (if given) into slot `slot` of item `index`.
    subroutine set_slot(occ, key, slot, index, functions, loads, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        integer(i4), intent(in) :: slot, index
        logical, intent(in) :: functions
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: f
        real(dp) :: x
        if (.not. occ%has(key)) return
        if (.not. functions) then
            call occ%get_real(key, x, st)
            if (st%ok()) call load_set_constant(loads, index, slot, x)
            return
        end if
        call occ%get_concept(key, f, st)
        if (st%failed()) return
        select type (f)
        class is (function_concept_t)
            call load_set_function(loads, index, slot, f)
        class default
            call occ%error_at(key, 'expected a function (DEFI_CONSTANTE, DEFI_FONCTION, ' // &
                'FORMULE), got ' // f%type_name(), st)
        end select
    end subroutine set_slot

end module load_commands
