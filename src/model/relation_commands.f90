!> The linear relations of AFFE_CHAR_MECA / AFFE_CHAR_MECA_F (Code_Aster U4.44.01) as load
!> items (model_loads RELATION items, eliminated by the analysis: doc/analysis.md "Linear
!> relations"): FACE_IMPO and ARETE_IMPO (their DX..DRZ as DDL_IMPO, DNOR / DTAN / DRNOR
!> as relations along the face's normal or the edge's tangent), LIAISON_DDL,
!> LIAISON_OBLIQUE, LIAISON_UNIF, LIAISON_SOLIDE, LIAISON_RBE3, LIAISON_GROUP; and the node
!> selection these keywords and DDL_IMPO share (TOUT, GROUP_MA, GROUP_NO, NOEUD, less
!> SANS_GROUP_MA and SANS_GROUP_NO).
module relation_commands
    use kinds, only: dp, i4
    use status, only: status_t, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use strings, only: string_t, to_text
    use deck_concept, only: concept_t
    use deck_command, only: keyword_set_t
    use mesh_types, only: mesh_t, find_node, nodes_of_group, nodes_of_cells, node_name
    use mesh_command_support, only: relocate_error, group_cells, all_cells, read_node_groups
    use model_types, only: ELEM_NONE
    use model_dof_numbering, only: COMPONENT_NAMES, N_COMPONENTS, DOF_DX, DOF_DY, DOF_DZ, &
        DOF_DRX
    use model_concept, only: model_concept_t
    use model_loads, only: load_set_t, load_add_item, load_set_constant, load_set_function, &
        load_add_relation, LOAD_RELATION, LOAD_DDL_IMPO
    use model_relations, only: relation_list_t, node_directions, nautical_frame, &
        rigid_body_relations, rbe3_coefficients, pair_nodes, shortest_edge, DIST_MIN_FRACTION
    use function_concept, only: function_concept_t
    use load_occurrences, only: locate_item, three_reals
    implicit none
    private

    public :: select_nodes, face_impo_item, liaison_ddl_item, liaison_oblique_item, &
        liaison_unif_item, liaison_solide_item, liaison_rbe3_item, liaison_group_item, &
        component_of

contains

    !> The nodes an occurrence designates: the union of TOUT (the nodes of the model's
    !> cells), GROUP_MA (the nodes of its cells), GROUP_NO and NOEUD, less the nodes of
    !> SANS_GROUP_MA's cells and of SANS_GROUP_NO (Code_Aster getnode). Distinct, increasing.
    !>  label : out, a name for messages (the first group, or TOUT)
    !>  st    : out, a group or node missing in the mesh, located at its keyword
    subroutine select_nodes(occ, mc, nodes, label, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        integer(i4), allocatable, intent(out) :: nodes(:)
        character(len=:), allocatable, intent(out) :: label
        type(status_t), intent(out) :: st
        logical, allocatable :: taken(:)
        integer(i4), allocatable :: cells(:), list(:)
        integer(i4) :: k
        allocate (taken(mc%mesh%n_nodes), source=.false.)
        label = ''
        if (occ%has('TOUT')) then
            cells = pack(all_cells(mc%mesh), mc%model%element /= ELEM_NONE)
            taken(nodes_of_cells(mc%mesh, cells)) = .true.
            label = 'TOUT'
        end if
        if (occ%has('GROUP_MA')) then
            call group_cells(occ, 'GROUP_MA', mc%mesh, cells, st)
            if (st%failed()) return
            taken(nodes_of_cells(mc%mesh, cells)) = .true.
            if (len(label) == 0) call first_name(occ, 'GROUP_MA', label)
        end if
        if (occ%has('GROUP_NO')) then
            call node_list(occ, 'GROUP_NO', mc%mesh, list, st)
            if (st%failed()) return
            taken(list) = .true.
            if (len(label) == 0) call first_name(occ, 'GROUP_NO', label)
        end if
        if (occ%has('NOEUD')) then
            call node_list(occ, 'NOEUD', mc%mesh, list, st)
            if (st%failed()) return
            taken(list) = .true.
            if (len(label) == 0) call first_name(occ, 'NOEUD', label)
        end if
        if (occ%has('SANS_GROUP_MA')) then
            call group_cells(occ, 'SANS_GROUP_MA', mc%mesh, cells, st)
            if (st%failed()) return
            taken(nodes_of_cells(mc%mesh, cells)) = .false.
        end if
        if (occ%has('SANS_GROUP_NO')) then
            call node_list(occ, 'SANS_GROUP_NO', mc%mesh, list, st)
            if (st%failed()) return
            taken(list) = .false.
        end if
        nodes = pack([(k, k = 1, mc%mesh%n_nodes)], taken)
    end subroutine select_nodes

    ! The first name given to `key`.
    subroutine first_name(occ, key, label)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        character(len=:), allocatable, intent(out) :: label
        type(string_t), allocatable :: names(:)
        type(status_t) :: st
        call occ%get_texts(key, names, st)
        label = key
        if (st%ok() .and. size(names) > 0) label = names(1)%s
    end subroutine first_name

    !> The nodes of GROUP_NO-like (its groups' nodes) or NOEUD-like (names) keyword `key`,
    !> in the order given, repeats kept.
    subroutine node_list(occ, key, mesh, nodes, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        type(mesh_t), intent(in) :: mesh
        integer(i4), allocatable, intent(out) :: nodes(:)
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        integer(i4), allocatable :: groups(:)
        integer(i4) :: k, n
        allocate (nodes(0))
        if (index(key, 'GROUP_NO') > 0) then
            call read_node_groups(occ, key, mesh, names, groups, st)
            if (st%failed()) return
            do k = 1, size(groups)
                nodes = [nodes, nodes_of_group(mesh, groups(k))]
            end do
        else
            call occ%get_texts(key, names, st)
            if (st%failed()) return
            do k = 1, size(names)
                n = find_node(mesh, names(k)%s, st)
                if (st%failed()) then
                    call relocate_error(occ, key, st)
                    return
                end if
                nodes = [nodes, n]
            end do
        end if
    end subroutine node_list

    !> CELL list of GROUP_MA-like keyword `key` less the cells of SANS_GROUP_MA.
    subroutine face_cells(occ, key, mesh, cells, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        type(mesh_t), intent(in) :: mesh
        integer(i4), allocatable, intent(out) :: cells(:)
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: without(:)
        logical, allocatable :: drop(:)
        call group_cells(occ, key, mesh, cells, st)
        if (st%failed()) return
        if (.not. occ%has('SANS_GROUP_MA')) return
        call group_cells(occ, 'SANS_GROUP_MA', mesh, without, st)
        if (st%failed()) return
        allocate (drop(mesh%n_cells), source=.false.)
        drop(without) = .true.
        cells = pack(cells, .not. drop(cells))
    end subroutine face_cells

    !> The component number (DOF_*) of a name DX .. DRZ, 0 for another.
    pure integer(i4) function component_of(name) result(comp)
        character(len=*), intent(in) :: name
        integer(i4) :: k
        comp = 0
        do k = 1, N_COMPONENTS
            if (trim(COMPONENT_NAMES(k)) == trim(name)) comp = k
        end do
    end function component_of

    ! Reads keyword `key` (if given) into value slot `slot` of item `index`.
    subroutine set_value(occ, key, slot, index, functions, loads, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        integer(i4), intent(in) :: slot, index
        logical, intent(in) :: functions
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: f
        real(dp) :: x
        loads%items(index)%slot_names(slot) = key
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
    end subroutine set_value

    ! A new RELATION item for the occurrence, located there.
    subroutine new_relation_item(occ, label, loads, index)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: label
        type(load_set_t), intent(inout) :: loads
        integer(i4), intent(out) :: index
        call load_add_item(loads, LOAD_RELATION, [integer(i4) ::], index, label)
        call locate_item(occ, loads, index)
    end subroutine new_relation_item

    ! Checks that node has component comp in the model; error at `key` otherwise.
    subroutine need_component(occ, key, mc, node, comp, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        type(model_concept_t), intent(in) :: mc
        integer(i4), intent(in) :: node, comp
        type(status_t), intent(out) :: st
        if (mc%dofs%equation(comp, node) > 0) return
        call occ%error_at(key, 'node ' // node_name(mc%mesh, node) // ' has no component ' // &
            trim(COMPONENT_NAMES(comp)) // ' in the model: no element carries it, a ' // &
            'relation cannot hold it', st, code=STATUS_MODEL_ERROR)
    end subroutine need_component

    !> FACE_IMPO (GROUP_MA's nodes less those of SANS_GROUP_MA's cells and SANS_GROUP_NO)
    !> and ARETE_IMPO: DX .. DRZ imposed on the face's nodes that have them (a component no node has is an error,
    !> Code_Aster CHARGES2_45); DNOR (u . n), DTAN (2D face or 3D edge: u . t) and DRNOR
    !> (3D: theta . n) as one relation per node, n and t the face's mean normal and tangent
    !> there (model_relations node_directions, Code_Aster cafaci, canort).
    !>  edge : in, ARETE_IMPO (its cells are lines of a 3D mesh; DTAN along them)
    subroutine face_impo_item(occ, mc, functions, edge, loads, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        logical, intent(in) :: functions, edge
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: cells(:), nodes(:)
        character(len=:), allocatable :: label
        character(len=3), parameter :: DOFS(6) = ['DX ', 'DY ', 'DZ ', 'DRX', 'DRY', 'DRZ']
        integer(i4) :: k, index
        logical :: any_value
        if (.not. occ%has('GROUP_MA')) then
            call occ%error_at('', occ%scope // ' needs GROUP_MA (the cells of the ' // &
                trim(merge('edge', 'face', edge)) // ')', st, code=STATUS_MODEL_ERROR)
            return
        end if
        ! the normals from GROUP_MA less SANS_GROUP_MA's cells (Code_Aster getelem), the
        ! nodes GROUP_MA's less those of SANS_GROUP_MA's cells and SANS_GROUP_NO (getnode)
        call face_cells(occ, 'GROUP_MA', mc%mesh, cells, st)
        if (st%failed()) return
        call select_nodes(occ, mc, nodes, label, st)
        if (st%failed()) return
        any_value = .false.
        do k = 1, 6
            if (occ%has(trim(DOFS(k)))) any_value = .true.
        end do
        if (any_value) then
            call load_add_item(loads, LOAD_DDL_IMPO, nodes, index, label)
            call locate_item(occ, loads, index)
            loads%items(index)%blocage = .true.     ! the components each node has
            do k = 1, 6
                if (.not. occ%has(trim(DOFS(k)))) cycle
                call set_value(occ, trim(DOFS(k)), k, index, functions, loads, st)
                if (st%failed()) return
                if (.not. any(mc%dofs%equation(k, nodes) > 0)) then
                    call occ%error_at(trim(DOFS(k)), 'no node of the ' // &
                        trim(merge('edge', 'face', edge)) // ' has component ' // &
                        trim(DOFS(k)) // ' in the model (Code_Aster CHARGES2_45)', st, &
                        code=STATUS_MODEL_ERROR)
                    return
                end if
            end do
        end if
        if (occ%has('DNOR')) call direction_relations(occ, mc, 'DNOR', cells, nodes, &
            .false., DOF_DX, functions, label, loads, st)
        if (st%failed()) return
        if (occ%has('DTAN')) then
            if (.not. edge .and. mc%mesh%dim == 3) then
                call occ%error_at('DTAN', 'DTAN is a 2D keyword of FACE_IMPO (a 3D face ' // &
                    'has no one tangent; Code_Aster CHARGES2_63)', st, code=STATUS_MODEL_ERROR)
                return
            end if
            call direction_relations(occ, mc, 'DTAN', cells, nodes, .true., DOF_DX, &
                functions, label, loads, st)
            if (st%failed()) return
        end if
        if (occ%has('DRNOR')) then
            if (mc%mesh%dim /= 3) then
                call occ%error_at('DRNOR', 'DRNOR needs a 3D mesh (the rotation about the ' // &
                    'normal of a shell face; Code_Aster CHARGES2_68)', st, &
                    code=STATUS_MODEL_ERROR)
                return
            end if
            call direction_relations(occ, mc, 'DRNOR', cells, nodes, .false., DOF_DRX, &
                functions, label, loads, st)
        end if
    end subroutine face_impo_item

    ! One relation per node: d . (component first .. first + dim - 1) = value, d the node's
    ! normal or tangent.
    subroutine direction_relations(occ, mc, key, cells, nodes, tangent, first, functions, &
                                   label, loads, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        character(len=*), intent(in) :: key, label
        integer(i4), intent(in) :: cells(:), nodes(:), first
        logical, intent(in) :: tangent, functions
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        real(dp), allocatable :: d(:, :)
        integer(i4) :: k, i, index, dim
        integer(i4), allocatable :: comps(:)
        allocate (d(3, size(nodes)))
        call node_directions(mc%mesh, cells, nodes, tangent, d, st)
        if (st%failed()) then
            call relocate_error(occ, key, st)
            return
        end if
        dim = mc%mesh%dim
        comps = [(first + i - 1, i = 1, dim)]
        call new_relation_item(occ, label, loads, index)
        call set_value(occ, key, 1_i4, index, functions, loads, st)
        if (st%failed()) return
        do k = 1, size(nodes)
            do i = 1, dim
                call need_component(occ, key, mc, nodes(k), comps(i), st)
                if (st%failed()) return
            end do
            call load_add_relation(loads, index, spread(nodes(k), 1, dim), comps, &
                d(1:dim, k), 1_i4, nodes(k))
        end do
    end subroutine direction_relations

    !> LIAISON_DDL: sum_i COEF_MULT(i) u(node_i, DDL(i)) = COEF_IMPO, the nodes of GROUP_NO
    !> (each group's in order) or NOEUD, one per DDL.
    subroutine liaison_ddl_item(occ, mc, functions, loads, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        logical, intent(in) :: functions
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: nodes(:), comps(:)
        type(string_t), allocatable :: ddl(:)
        real(dp), allocatable :: coefs(:)
        character(len=:), allocatable :: key, label
        integer(i4) :: k, index
        key = 'NOEUD'
        if (occ%has('GROUP_NO')) key = 'GROUP_NO'
        call node_list(occ, key, mc%mesh, nodes, st)
        if (st%ok()) call occ%get_texts('DDL', ddl, st)
        if (st%failed()) return
        if (.not. occ%has('COEF_MULT')) then
            call occ%error_at('COEF_MULT_FONC', 'COEF_MULT_FONC (coefficients that are ' // &
                'functions) is not built; give COEF_MULT', st, code=STATUS_NOT_IMPLEMENTED)
            return
        end if
        call occ%get_reals('COEF_MULT', coefs, st)
        if (st%failed()) return
        if (size(nodes) /= size(ddl) .or. size(coefs) /= size(ddl)) then
            call occ%error_at('DDL', to_text(size(nodes, kind=i4)) // ' node(s) in ' // key // &
                ', ' // to_text(size(ddl, kind=i4)) // ' DDL and ' // &
                to_text(size(coefs, kind=i4)) // ' COEF_MULT: LIAISON_DDL takes one of ' // &
                'each per term', st, code=STATUS_MODEL_ERROR)
            return
        end if
        allocate (comps(size(ddl)))
        do k = 1, size(ddl)
            comps(k) = component_of(ddl(k)%s)
            call need_component(occ, key, mc, nodes(k), comps(k), st)
            if (st%failed()) return
        end do
        call first_name(occ, key, label)
        call new_relation_item(occ, label, loads, index)
        call set_value(occ, 'COEF_IMPO', 1_i4, index, functions, loads, st)
        if (st%failed()) return
        call load_add_relation(loads, index, nodes, comps, coefs, 1_i4, nodes(1))
    end subroutine liaison_ddl_item

    !> LIAISON_OBLIQUE: at each node, the components DX .. DRZ given, taken in the frame of
    !> ANGL_NAUT (rows of nautical_frame), equal to their values: e_k . u = value.
    subroutine liaison_oblique_item(occ, mc, functions, loads, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        logical, intent(in) :: functions
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: nodes(:), comps(:)
        real(dp), allocatable :: angles(:), coefs(:)
        character(len=:), allocatable :: label
        character(len=3), parameter :: DOFS(6) = ['DX ', 'DY ', 'DZ ', 'DRX', 'DRY', 'DRZ']
        real(dp) :: p(3, 3)
        integer(i4) :: k, n, index, base, j
        call select_nodes(occ, mc, nodes, label, st)
        if (st%ok()) call occ%get_reals('ANGL_NAUT', angles, st)
        if (st%failed()) return
        call nautical_frame(angles, p)
        call new_relation_item(occ, label, loads, index)
        do k = 1, 6
            call set_value(occ, trim(DOFS(k)), k, index, functions, loads, st)
            if (st%failed()) return
        end do
        do n = 1, size(nodes)
            do k = 1, 6
                if (.not. occ%has(trim(DOFS(k)))) cycle
                base = DOF_DX
                if (k > 3) base = DOF_DRX
                ! the terms with a coefficient; each on a component the node must have
                comps = [integer(i4) ::]
                coefs = [real(dp) ::]
                do j = 1, 3
                    if (.not. abs(p(k - base + 1, j)) > 0.0_dp) cycle
                    call need_component(occ, trim(DOFS(k)), mc, nodes(n), base + j - 1, st)
                    if (st%failed()) return
                    comps = [comps, base + j - 1]
                    coefs = [coefs, p(k - base + 1, j)]
                end do
                call load_add_relation(loads, index, spread(nodes(n), 1, size(comps)), comps, &
                    coefs, k, nodes(n))
            end do
        end do
    end subroutine liaison_oblique_item

    !> LIAISON_UNIF: every component of DDL equal at the nodes: u(n_i) - u(n_1) = 0.
    subroutine liaison_unif_item(occ, mc, loads, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: nodes(:)
        type(string_t), allocatable :: ddl(:)
        character(len=:), allocatable :: label
        integer(i4) :: k, i, comp, index
        call select_nodes(occ, mc, nodes, label, st)
        if (st%ok()) call occ%get_texts('DDL', ddl, st)
        if (st%failed()) return
        call new_relation_item(occ, label, loads, index)
        do i = 1, size(ddl)
            comp = component_of(ddl(i)%s)
            do k = 1, size(nodes)
                call need_component(occ, 'DDL', mc, nodes(k), comp, st)
                if (st%failed()) return
                if (k == 1) cycle
                call load_add_relation(loads, index, [nodes(k), nodes(1)], [comp, comp], &
                    [1.0_dp, -1.0_dp], 0_i4, nodes(k))
            end do
        end do
    end subroutine liaison_unif_item

    !> LIAISON_SOLIDE: the nodes move as one rigid body (model_relations
    !> rigid_body_relations); the item records the body's nodes (its cells store no
    !> energy). One node: nothing (Code_Aster CHARGES2_17).
    subroutine liaison_solide_item(occ, mc, loads, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: nodes(:)
        character(len=:), allocatable :: label
        type(relation_list_t) :: list
        real(dp) :: dist_min
        integer(i4) :: r, index
        call select_nodes(occ, mc, nodes, label, st)
        if (st%failed()) return
        if (size(nodes) < 2) return
        dist_min = DIST_MIN_FRACTION * shortest_edge(mc%mesh)
        if (occ%has('DIST_MIN')) call occ%get_real('DIST_MIN', dist_min, st)
        if (st%failed()) return
        call rigid_body_relations(mc%mesh, mc%dofs, nodes, dist_min, list, st)
        if (st%failed()) then
            call relocate_error(occ, merge('GROUP_MA', 'GROUP_NO', occ%has('GROUP_MA')), st)
            return
        end if
        call new_relation_item(occ, label, loads, index)
        loads%items(index)%solid_nodes = nodes
        do r = 1, list%n
            call load_add_relation(loads, index, list%node(list%ptr(r):list%ptr(r + 1) - 1), &
                list%comp(list%ptr(r):list%ptr(r + 1) - 1), &
                list%coef(list%ptr(r):list%ptr(r + 1) - 1), 0_i4, nodes(1))
        end do
    end subroutine liaison_solide_item

    !> LIAISON_RBE3: the master node's DDL_MAIT follow the weighted least-squares rigid
    !> motion of the slaves' DDL_ESCL ('DX-DY-DZ', one string for every slave or one per
    !> slave), COEF_ESCL the weights (one, or one per slave): model_relations
    !> rbe3_coefficients (Code_Aster carbe3). Terms on components a slave lacks must have a
    !> zero coefficient.
    subroutine liaison_rbe3_item(occ, mc, loads, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: masters(:), slaves(:), nodes(:), comps(:)
        type(string_t), allocatable :: ddl_master(:), ddl_slave(:)
        real(dp), allocatable :: weights(:), b(:, :), coefs(:)
        logical, allocatable :: chosen(:, :)
        integer(i4) :: i, k, m, index, col
        character(len=:), allocatable :: label
        if (.not. occ%has('GROUP_NO_MAIT') .or. .not. occ%has('GROUP_NO_ESCL')) then
            call occ%error_at('', 'LIAISON_RBE3 needs GROUP_NO_MAIT and GROUP_NO_ESCL', st, &
                code=STATUS_MODEL_ERROR)
            return
        end if
        call node_list(occ, 'GROUP_NO_MAIT', mc%mesh, masters, st)
        if (st%ok()) call node_list(occ, 'GROUP_NO_ESCL', mc%mesh, slaves, st)
        if (st%ok()) call occ%get_texts('DDL_MAIT', ddl_master, st)
        if (st%ok()) call occ%get_texts('DDL_ESCL', ddl_slave, st)
        if (st%ok()) call occ%get_reals('COEF_ESCL', weights, st)
        if (st%failed()) return
        if (size(masters) /= 1) then
            call occ%error_at('GROUP_NO_MAIT', 'the master group holds ' // &
                to_text(size(masters, kind=i4)) // ' nodes: one is needed ' // &
                '(Code_Aster MODELISA10_9)', st, code=STATUS_MODEL_ERROR)
            return
        end if
        if (size(ddl_slave) /= 1 .and. size(ddl_slave) /= size(slaves)) then
            call occ%error_at('DDL_ESCL', to_text(size(ddl_slave, kind=i4)) // ' values ' // &
                'for ' // to_text(size(slaves, kind=i4)) // ' slave nodes: give one, or ' // &
                'one per slave (Code_Aster MODELISA10_10)', st, code=STATUS_MODEL_ERROR)
            return
        end if
        if (size(weights) /= 1 .and. size(weights) /= size(slaves)) then
            call occ%error_at('COEF_ESCL', to_text(size(weights, kind=i4)) // ' values ' // &
                'for ' // to_text(size(slaves, kind=i4)) // ' slave nodes: give one, or ' // &
                'one per slave (Code_Aster MODELISA10_13)', st, code=STATUS_MODEL_ERROR)
            return
        end if
        if (size(weights) == 1) weights = spread(weights(1), 1, size(slaves))
        allocate (chosen(6, size(slaves)))
        do i = 1, size(slaves)
            call slave_components(occ, ddl_slave(min(i, size(ddl_slave)))%s, chosen(:, i), st)
            if (st%failed()) return
        end do
        call rbe3_coefficients(mc%mesh, masters(1), slaves, chosen, weights, b, st)
        if (st%failed()) then
            call relocate_error(occ, 'GROUP_NO_ESCL', st)
            return
        end if
        call first_name(occ, 'GROUP_NO_MAIT', label)
        call new_relation_item(occ, label, loads, index)
        do m = 1, size(ddl_master)
            k = component_of(ddl_master(m)%s)
            call need_component(occ, 'DDL_MAIT', mc, masters(1), k, st)
            if (st%failed()) return
            nodes = [masters(1)]
            comps = [k]
            coefs = [-1.0_dp]
            col = 0
            do i = 1, size(slaves)
                do k = 1, 6
                    if (.not. chosen(k, i)) cycle
                    col = col + 1
                    if (.not. abs(b(component_of(ddl_master(m)%s), col)) > 0.0_dp) cycle
                    call need_component(occ, 'DDL_ESCL', mc, slaves(i), k, st)
                    if (st%failed()) return
                    nodes = [nodes, slaves(i)]
                    comps = [comps, k]
                    coefs = [coefs, b(component_of(ddl_master(m)%s), col)]
                end do
            end do
            call load_add_relation(loads, index, nodes, comps, coefs, 0_i4, masters(1))
        end do
    end subroutine liaison_rbe3_item

    ! 'DX-DY-DZ' -> chosen(1:3) = .true.
    subroutine slave_components(occ, text, chosen, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: text
        logical, intent(out) :: chosen(6)
        type(status_t), intent(out) :: st
        integer :: i, j, comp
        chosen = .false.
        i = 1
        do while (i <= len_trim(text))
            j = index(text(i:) // '-', '-') + i - 1
            comp = component_of(text(i:j - 1))
            if (comp == 0) then
                call occ%error_at('DDL_ESCL', '''' // text(i:j - 1) // ''' in ''' // &
                    trim(text) // ''' is not a component DX .. DRZ (Code_Aster ' // &
                    'MODELISA10_11)', st)
                return
            end if
            chosen(comp) = .true.
            i = j + 1
        end do
    end subroutine slave_components

    !> LIAISON_GROUP: for each pair (n1, n2) of the two groups (model_relations pair_nodes:
    !> n2 the nearest to n1's image by TRAN, ANGL_NAUT about CENTRE), sum COEF_MULT_1 u(n1,
    !> DDL_1) + sum COEF_MULT_2 u(n2, DDL_2) = COEF_IMPO; DNOR is the normal component on
    !> a group given by its cells (GROUP_MA_i). SANS_GROUP_NO drops the pairs of its nodes.
    subroutine liaison_group_item(occ, mc, functions, loads, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        logical, intent(in) :: functions
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: nodes1(:), nodes2(:), cells1(:), cells2(:), partner(:)
        integer(i4), allocatable :: without(:), nodes(:), comps(:)
        type(string_t), allocatable :: ddl1(:), ddl2(:)
        real(dp), allocatable :: c1(:), c2(:), n1(:, :), n2(:, :), coefs(:), v(:)
        real(dp) :: tran(3), centre(3), frame(3, 3)
        character(len=:), allocatable :: label
        integer(i4) :: k, index, j
        call group_side(occ, '1', mc, nodes1, cells1, st)
        if (st%ok()) call group_side(occ, '2', mc, nodes2, cells2, st)
        if (st%ok()) call occ%get_texts('DDL_1', ddl1, st)
        if (st%ok()) call occ%get_texts('DDL_2', ddl2, st)
        if (st%ok()) call occ%get_reals('COEF_MULT_1', c1, st)
        if (st%ok()) call occ%get_reals('COEF_MULT_2', c2, st)
        if (st%failed()) return
        if (size(c1) /= size(ddl1) .or. size(c2) /= size(ddl2)) then
            call occ%error_at('COEF_MULT_1', 'COEF_MULT_1 and COEF_MULT_2 take one value ' // &
                'per DDL_1 and DDL_2', st, code=STATUS_MODEL_ERROR)
            return
        end if
        tran = 0.0_dp
        centre = 0.0_dp
        call nautical_frame([0.0_dp], frame)
        if (occ%has('TRAN')) call three_reals(occ, 'TRAN', tran, st)
        if (st%ok() .and. occ%has('CENTRE')) call three_reals(occ, 'CENTRE', centre, st)
        if (st%ok() .and. occ%has('ANGL_NAUT')) then
            call occ%get_reals('ANGL_NAUT', v, st)
            if (st%ok()) call nautical_frame(v, frame)
        end if
        if (st%failed()) return
        if (occ%has('SANS_GROUP_NO')) then
            call node_list(occ, 'SANS_GROUP_NO', mc%mesh, without, st)
            if (st%failed()) return
        else
            allocate (without(0))
        end if
        allocate (partner(size(nodes1)))
        call pair_nodes(mc%mesh, nodes1, nodes2, tran, frame, centre, partner, st)
        if (st%failed()) then
            call relocate_error(occ, merge('GROUP_MA_2', 'GROUP_NO_2', occ%has('GROUP_MA_2')), &
                st)
            return
        end if
        call normals_if_needed(occ, mc, ddl1, cells1, nodes1, '1', n1, st)
        if (st%ok()) call normals_if_needed(occ, mc, ddl2, cells2, partner, '2', n2, st)
        if (st%failed()) return
        call first_name(occ, merge('GROUP_MA_1', 'GROUP_NO_1', occ%has('GROUP_MA_1')), label)
        call new_relation_item(occ, label, loads, index)
        call set_value(occ, 'COEF_IMPO', 1_i4, index, functions, loads, st)
        if (st%failed()) return
        do k = 1, size(nodes1)
            if (any(without == nodes1(k)) .or. any(without == partner(k))) cycle
            nodes = [integer(i4) ::]
            comps = [integer(i4) ::]
            coefs = [real(dp) ::]
            do j = 1, size(ddl1)
                call add_terms(ddl1(j)%s, nodes1(k), c1(j), n1(:, k), 'DDL_1', st)
                if (st%failed()) return
            end do
            do j = 1, size(ddl2)
                call add_terms(ddl2(j)%s, partner(k), c2(j), n2(:, k), 'DDL_2', st)
                if (st%failed()) return
            end do
            call load_add_relation(loads, index, nodes, comps, coefs, 1_i4, nodes1(k))
        end do
    contains
        subroutine add_terms(name, node, c, normal, key, st)
            character(len=*), intent(in) :: name, key
            integer(i4), intent(in) :: node
            real(dp), intent(in) :: c, normal(:)
            type(status_t), intent(out) :: st
            integer(i4) :: i, comp
            if (name == 'DNOR') then
                do i = 1, mc%mesh%dim
                    call need_component(occ, key, mc, node, DOF_DX + i - 1, st)
                    if (st%failed()) return
                    nodes = [nodes, node]
                    comps = [comps, DOF_DX + i - 1]
                    coefs = [coefs, c * normal(i)]
                end do
                return
            end if
            comp = component_of(name)
            call need_component(occ, key, mc, node, comp, st)
            if (st%failed()) return
            nodes = [nodes, node]
            comps = [comps, comp]
            coefs = [coefs, c]
        end subroutine add_terms
    end subroutine liaison_group_item

    ! The nodes (and cells, empty for GROUP_NO_i) of side `side` of LIAISON_GROUP.
    subroutine group_side(occ, side, mc, nodes, cells, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=1), intent(in) :: side
        type(model_concept_t), intent(in) :: mc
        integer(i4), allocatable, intent(out) :: nodes(:), cells(:)
        type(status_t), intent(out) :: st
        logical, allocatable :: taken(:)
        integer(i4) :: k
        if (occ%has('GROUP_MA_' // side)) then
            call group_cells(occ, 'GROUP_MA_' // side, mc%mesh, cells, st)
            if (st%failed()) return
            nodes = nodes_of_cells(mc%mesh, cells)
        else
            allocate (cells(0))
            call node_list(occ, 'GROUP_NO_' // side, mc%mesh, nodes, st)
            if (st%failed()) return
            allocate (taken(mc%mesh%n_nodes), source=.false.)
            taken(nodes) = .true.
            nodes = pack([(k, k = 1, mc%mesh%n_nodes)], taken)
        end if
    end subroutine group_side

    ! The normals at `nodes` when DDL_i asks for DNOR (zero vectors otherwise).
    subroutine normals_if_needed(occ, mc, ddl, cells, nodes, side, normals, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        type(string_t), intent(in) :: ddl(:)
        integer(i4), intent(in) :: cells(:), nodes(:)
        character(len=1), intent(in) :: side
        real(dp), allocatable, intent(out) :: normals(:, :)
        type(status_t), intent(out) :: st
        integer(i4) :: k
        allocate (normals(3, size(nodes)), source=0.0_dp)
        if (.not. any([(ddl(k)%s == 'DNOR', k = 1, size(ddl))])) return
        if (size(cells) == 0) then
            call occ%error_at('DDL_' // side, 'DNOR needs the cells of the group ' // &
                '(GROUP_MA_' // side // ') to take their normal', st, code=STATUS_MODEL_ERROR)
            return
        end if
        call node_directions(mc%mesh, cells, nodes, .false., normals, st)
        call relocate_error(occ, 'GROUP_MA_' // side, st)
    end subroutine normals_if_needed

end module relation_commands
