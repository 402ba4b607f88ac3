!> PROJ_CHAMP (Code_Aster U4.72.05, code_aster/Cata/Commands/proj_champ.py), METHODE
!> 'COLLOCATION' (and 'AUTO', which is collocation for nodal fields): nodal fields of a
!> source mesh (MODELE_1 or MAILLAGE_1) interpolated at the nodes of a target mesh
!> (MODELE_2 or MAILLAGE_2) by the shape functions of the source cell holding each node
!> (field_projection; doc/fields.md "PROJ_CHAMP").
!>  - source cells: VIS_A_VIS's TOUT_1 / GROUP_MA_1 / MAILLE_1 / GROUP_NO_1 (the cells all of
!>    whose nodes are in it), else every cell (of MODELE_1: those with an element), of the
!>    dimension of CAS_FIGURE ('2D', '2.5D': triangles and quadrangles; '1.5D': segments;
!>    by default the highest dimension present);
!>  - target nodes: VIS_A_VIS's TOUT_2 / GROUP_MA_2 / GROUP_NO_2 / NOEUD_2, else every node
!>    (of MODELE_2: the nodes of its elements); each VIS_A_VIS occurrence projects its
!>    nodes from its cells, later ones over earlier ones;
!>  - a node in no cell takes the nearest cell, unless farther than DISTANCE_MAX; ALARME='OUI'
!>    warns of such nodes (farther than DISTANCE_ALARME when given); PROL_VALE (PROL_ZERO
!>    'OUI': 0) is the value of every component at the nodes not projected.
!> RESULTAT: a result of its type on the target mesh, with NOM_CHAM (default every nodal
!> field) at the instants asked for; CHAM_GD: a field; PROJECTION='NON': the
!> correspondence (corresp_2_mailla), which MATR_PROJECTION reuses.
module proj_champ_command
    use keyword_relocation, only: relocate => relocate_error
    use mesh_command_support, only: mark_cells, mark_nodes
    use kinds, only: dp, i4
    use status, only: status_t, clear_status, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use strings, only: string_t, to_text, real_e13
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, node_name
    use mesh_cell_shapes, only: CELL_TYPE_DIM
    use model_types, only: model_t, ELEM_NONE
    use model_concept, only: model_concept_t
    use mesh_concept, only: mesh_concept_t
    use model_cara_elem, only: cara_elem_init
    use model_material, only: material_field_init
    use field_types, only: field_t, FIELD_NOEU
    use field_concept, only: field_concept_t
    use field_support, only: mesh_of_support
    use result_fields, only: result_fields_init, result_add_instant, result_put_field, &
        result_stored_names
    use analysis_result, only: result_concept_t
    use result_access, only: result_field_at
    use result_instants, only: selected_instants
    use field_projection, only: projection_t, projection_build, projection_merge, &
        project_node_field, cells_of_dimension
    use projection_concept, only: projection_concept_t
    implicit none
    private

    !> The two sides of a projection.
    type :: sides_t
        class(concept_t), pointer :: source => null(), target => null()
        type(mesh_t), pointer :: mesh1 => null(), mesh2 => null()
        type(model_concept_t), pointer :: model1 => null(), model2 => null()
    end type sides_t

    public :: run_proj_champ

contains

    !> Handler of PROJ_CHAMP (registered with reuse: reuse=R projects into R).
    !>  st : located errors: a METHODE not built, a field of another mesh, an element field,
    !>       an unknown group, no source cell of the dimension asked for
    subroutine run_proj_champ(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(projection_concept_t), allocatable :: corr
        class(concept_t), pointer :: p
        character(len=:), allocatable :: projection, method
        projection = 'OUI'
        if (cmd%has('PROJECTION')) call cmd%get_text('PROJECTION', projection, st)
        if (st%failed()) return
        method = merge('AUTO       ', 'COLLOCATION', projection == 'OUI')
        if (cmd%has('METHODE')) call cmd%get_text('METHODE', method, st)
        if (st%failed()) return
        method = trim(method)
        if (method /= 'AUTO' .and. method /= 'COLLOCATION') then
            call cmd%error_at('METHODE', 'METHODE=''' // method // ''' is not built in ' // &
                'parasol (COLLOCATION, and AUTO as collocation, are)', st, &
                STATUS_NOT_IMPLEMENTED)
            return
        end if
        if (cmd%has('TRANSF_GEOM_1') .or. cmd%has('TRANSF_GEOM_2')) then
            call cmd%error_at(trim(merge('TRANSF_GEOM_1', 'TRANSF_GEOM_2', &
                cmd%has('TRANSF_GEOM_1'))), 'TRANSF_GEOM_1/2 are not built in parasol', st, &
                STATUS_NOT_IMPLEMENTED)
            return
        end if
        allocate (corr)
        if (cmd%has('MATR_PROJECTION')) then
            call cmd%get_concept('MATR_PROJECTION', p, st)
            if (st%failed()) return
            select type (p)
            type is (projection_concept_t)
                corr = p
            class default
                call cmd%error_at('MATR_PROJECTION', 'expected a corresp_2_mailla ' // &
                    '(PROJ_CHAMP with PROJECTION=''NON''), got ' // p%type_name(), st)
                return
            end select
        else
            call build_correspondence(ctx, cmd, corr, st)
            if (st%failed()) return
        end if
        if (projection == 'NON') then
            call move_alloc(corr, result)
            return
        end if
        if (cmd%has('CHAM_GD')) then
            call project_field_concept(ctx, cmd, corr, result, st)
        else
            call project_result(ctx, cmd, corr, result, st)
        end if
    end subroutine run_proj_champ

    ! The correspondence of MODELE_1/MAILLAGE_1, MODELE_2/MAILLAGE_2 and VIS_A_VIS.
    subroutine build_correspondence(ctx, cmd, corr, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(projection_concept_t), intent(inout) :: corr
        type(status_t), intent(out) :: st
        type(sides_t) :: sides
        type(projection_t) :: one
        type(keyword_set_t) :: occ
        integer(i4), allocatable :: cells(:), nodes(:)
        character(len=:), allocatable :: figure
        real(dp) :: max_distance
        integer(i4) :: k, n_occ
        call read_side(cmd, 'MODELE_1', 'MAILLAGE_1', sides%source, sides%mesh1, &
            sides%model1, st)
        if (st%ok()) call read_side(cmd, 'MODELE_2', 'MAILLAGE_2', sides%target, &
            sides%mesh2, sides%model2, st)
        if (st%failed()) return
        corr%source => sides%source
        corr%target => sides%target
        max_distance = -1.0_dp
        if (cmd%has('DISTANCE_MAX')) call cmd%get_real('DISTANCE_MAX', max_distance, st)
        figure = ''
        if (st%ok() .and. cmd%has('CAS_FIGURE')) call cmd%get_text('CAS_FIGURE', figure, st)
        if (st%failed()) return
        n_occ = cmd%count('VIS_A_VIS')
        do k = 0, n_occ
            if (k == 0 .and. n_occ > 0) cycle
            if (k == 0) then
                call all_cells(sides%mesh1, sides%model1, cells)
                call all_nodes(sides%mesh2, sides%model2, nodes)
                call cells_for_figure(cmd, 'CAS_FIGURE', figure, sides%mesh1, cells, st)
                if (st%failed()) return
                call projection_build(sides%mesh1, cells, sides%mesh2, nodes, max_distance, &
                    one, st)
                if (st%failed()) then
                    call relocate(cmd, trim(merge('MODELE_1  ', 'MAILLAGE_1', &
                        associated(sides%model1))), st)
                    return
                end if
            else
                occ = cmd%occurrence('VIS_A_VIS', k)
                call occurrence_sides(occ, sides, cells, nodes, st)
                if (st%failed()) return
                if (occ%has('CAS_FIGURE')) then
                    block
                        character(len=:), allocatable :: own
                        call occ%get_text('CAS_FIGURE', own, st)
                        if (st%ok()) call cells_for_figure(occ, 'CAS_FIGURE', own, &
                            sides%mesh1, cells, st)
                    end block
                else
                    call cells_for_figure(occ, 'GROUP_MA_1', figure, sides%mesh1, cells, st)
                end if
                if (st%failed()) return
                call projection_build(sides%mesh1, cells, sides%mesh2, nodes, max_distance, &
                    one, st)
                if (st%failed()) then
                    call relocate(occ, 'GROUP_MA_1', st)
                    return
                end if
            end if
            call projection_merge(corr%proj, one)
        end do
        call report_distances(ctx, cmd, sides%mesh2, corr%proj, max_distance, st)
    end subroutine build_correspondence

    ! MODELE_x or MAILLAGE_x: the concept, its mesh and (MODELE_x) the model.
    subroutine read_side(cmd, model_key, mesh_key, concept, mesh, model, st)
        type(command_t), intent(in) :: cmd
        character(len=*), intent(in) :: model_key, mesh_key
        class(concept_t), pointer, intent(out) :: concept
        type(mesh_t), pointer, intent(out) :: mesh
        type(model_concept_t), pointer, intent(out) :: model
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: key
        model => null()
        mesh => null()
        key = mesh_key
        if (cmd%has(model_key)) key = model_key
        if (.not. cmd%has(key)) then
            call cmd%error_at(key, 'give ' // model_key // ' or ' // mesh_key, st, &
                STATUS_MODEL_ERROR)
            return
        end if
        call cmd%get_concept(key, concept, st)
        if (st%failed()) return
        select type (concept)
        type is (model_concept_t)
            model => concept
            mesh => concept%mesh
        type is (mesh_concept_t)
            mesh => concept%mesh
        class default
            call cmd%error_at(key, 'expected a modele or a maillage, got ' // &
                concept%type_name(), st)
        end select
    end subroutine read_side

    ! Every cell of the mesh (with a model: those carrying an element).
    subroutine all_cells(mesh, model, cells)
        type(mesh_t), intent(in) :: mesh
        type(model_concept_t), pointer, intent(in) :: model
        integer(i4), allocatable, intent(out) :: cells(:)
        integer(i4) :: c
        if (associated(model)) then
            cells = pack([(c, c = 1, mesh%n_cells)], model%model%element /= ELEM_NONE)
        else
            cells = [(c, c = 1, mesh%n_cells)]
        end if
    end subroutine all_cells

    ! Every node of the mesh (with a model: the nodes of its elements).
    subroutine all_nodes(mesh, model, nodes)
        type(mesh_t), intent(in) :: mesh
        type(model_concept_t), pointer, intent(in) :: model
        integer(i4), allocatable, intent(out) :: nodes(:)
        logical, allocatable :: mask(:)
        integer(i4) :: c, n
        allocate (mask(mesh%n_nodes), source=.not. associated(model))
        if (associated(model)) then
            do c = 1, mesh%n_cells
                if (model%model%element(c) == ELEM_NONE) cycle
                mask(mesh%cell_nodes(mesh%cell_ptr(c):mesh%cell_ptr(c + 1) - 1)) = .true.
            end do
        end if
        nodes = pack([(n, n = 1, mesh%n_nodes)], mask)
    end subroutine all_nodes

    ! The cells of the dimension of CAS_FIGURE ('' : the highest present).
    subroutine cells_for_figure(kws, key, figure, mesh, cells, st)
        class(keyword_set_t), intent(in) :: kws
        character(len=*), intent(in) :: key, figure
        type(mesh_t), intent(in) :: mesh
        integer(i4), allocatable, intent(inout) :: cells(:)
        type(status_t), intent(out) :: st
        integer(i4) :: dim, k
        select case (figure)
        case ('2D', '2.5D')
            dim = 2
        case ('1.5D')
            dim = 1
        case ('')
            dim = 0
            do k = 1, size(cells, kind=i4)
                dim = max(dim, CELL_TYPE_DIM(mesh%cell_type(cells(k))))
            end do
            if (dim == 0) dim = 2
        case default
            call kws%error_at(key, 'CAS_FIGURE=''' // figure // ''' is not built in ' // &
                'parasol (its cells have no volume: 2D, 2.5D and 1.5D are)', st, &
                STATUS_NOT_IMPLEMENTED)
            return
        end select
        cells = cells_of_dimension(mesh, cells, dim)
        if (size(cells) == 0) call kws%error_at(key, 'no cell of dimension ' // &
            to_text(dim) // ' to project on', st, STATUS_MODEL_ERROR)
    end subroutine cells_for_figure

    ! A VIS_A_VIS occurrence: its source cells and target nodes.
    subroutine occurrence_sides(occ, sides, cells, nodes, st)
        type(keyword_set_t), intent(in) :: occ
        type(sides_t), intent(in) :: sides
        integer(i4), allocatable, intent(out) :: cells(:), nodes(:)
        type(status_t), intent(out) :: st
        logical, allocatable :: in1(:), nodes1(:), in2(:)
        integer(i4), allocatable :: every(:)
        integer(i4) :: c, n
        associate (m1 => sides%mesh1, m2 => sides%mesh2)
            allocate (in1(m1%n_cells), source=occ%has('TOUT_1'))
            call mark_cells(occ, 'GROUP_MA_1', 'MAILLE_1', m1, in1, st)
            if (st%failed()) return
            if (occ%has('GROUP_NO_1') .or. occ%has('NOEUD_1')) then
                allocate (nodes1(m1%n_nodes), source=.false.)
                call mark_nodes(occ, 'GROUP_NO_1', 'NOEUD_1', m1, nodes1, st)
                if (st%failed()) return
                do c = 1, m1%n_cells
                    if (all(nodes1(m1%cell_nodes(m1%cell_ptr(c):m1%cell_ptr(c + 1) - 1)))) &
                        in1(c) = .true.
                end do
            end if
            call all_cells(m1, sides%model1, every)
            cells = pack(every, in1(every))
            allocate (in2(m2%n_nodes), source=.false.)
            if (occ%has('TOUT_2')) then
                call all_nodes(m2, sides%model2, nodes)
                in2(nodes) = .true.
            end if
            if (occ%has('GROUP_MA_2')) then
                block
                    logical, allocatable :: cells2(:)
                    allocate (cells2(m2%n_cells), source=.false.)
                    call mark_cells(occ, 'GROUP_MA_2', 'MAILLE_2', m2, cells2, st)
                    if (st%failed()) return
                    do c = 1, m2%n_cells
                        if (cells2(c)) in2(m2%cell_nodes(m2%cell_ptr(c):m2%cell_ptr(c + 1) - 1)) &
                            = .true.
                    end do
                end block
            end if
            call mark_nodes(occ, 'GROUP_NO_2', 'NOEUD_2', m2, in2, st)
            if (st%failed()) return
            nodes = pack([(n, n = 1, m2%n_nodes)], in2)
        end associate
    end subroutine occurrence_sides

    ! Marks the cells of GROUP_MA-like key `groups` and MAILLE-like key `names`.

    ! Marks the nodes of GROUP_NO-like key `groups` and NOEUD-like key `names`.

    ! The .mess line of the search, and ALARME's warnings: nodes found in no cell (farther
    ! than DISTANCE_ALARME when given) and nodes beyond DISTANCE_MAX.
    subroutine report_distances(ctx, cmd, mesh2, proj, max_distance, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(mesh_t), intent(in) :: mesh2
        type(projection_t), intent(in) :: proj
        real(dp), intent(in) :: max_distance
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: alarm
        real(dp) :: threshold
        integer(i4) :: n_far, worst, n
        alarm = 'OUI'
        if (cmd%has('ALARME')) call cmd%get_text('ALARME', alarm, st)
        threshold = 0.0_dp
        if (st%ok() .and. cmd%has('DISTANCE_ALARME')) &
            call cmd%get_real('DISTANCE_ALARME', threshold, st)
        if (st%failed()) return
        call ctx%write_mess('    PROJ_CHAMP: ' // to_text(count(proj%projected)) // &
            ' node(s) projected, ' // to_text(count(proj%outside .and. proj%projected)) // &
            ' from outside the source cells')
        if (alarm /= 'OUI') return
        n_far = 0
        worst = 0
        do n = 1, proj%n_targets
            if (.not. (proj%projected(n) .and. proj%outside(n))) cycle
            if (proj%distance(n) <= threshold) cycle
            n_far = n_far + 1
            if (worst == 0) then
                worst = n
            else if (proj%distance(n) > proj%distance(worst)) then
                worst = n
            end if
        end do
        if (n_far > 0) call warn(ctx, cmd, 'PROJ_CHAMP', to_text(n_far) // ' node(s) of ' // &
            'the target lie in no source cell and take the nearest (the farthest: ' // &
            node_name(mesh2, worst) // ' at ' // real_e13(proj%distance(worst)) // ')')
        if (max_distance >= 0.0_dp) then
            n_far = count(proj%outside .and. .not. proj%projected)
            if (n_far > 0) call warn(ctx, cmd, 'DISTANCE_MAX', to_text(n_far) // &
                ' node(s) of the target are farther than DISTANCE_MAX from every source ' // &
                'cell: not projected')
        end if
    end subroutine report_distances

    ! A located warning line at `key` of the command.
    subroutine warn(ctx, cmd, key, message)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        character(len=*), intent(in) :: key, message
        character(len=:), allocatable :: file
        integer :: line, col
        call cmd%location(key, file, line, col)
        call ctx%write_warning(file // ':' // to_text(int(line, i4)) // ':' // &
            to_text(int(col, i4)) // ': warning: PROJ_CHAMP: ' // message)
    end subroutine warn

    ! PROL_VALE (PROL_ZERO='OUI': 0): present or not.
    subroutine prolongation(cmd, has, value, st)
        type(command_t), intent(in) :: cmd
        logical, intent(out) :: has
        real(dp), intent(out) :: value
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: zero
        has = cmd%has('PROL_VALE')
        value = 0.0_dp
        if (has) then
            call cmd%get_real('PROL_VALE', value, st)
        else if (cmd%has('PROL_ZERO')) then
            call cmd%get_text('PROL_ZERO', zero, st)
            has = zero == 'OUI'
        end if
    end subroutine prolongation

    ! One field, with PROL_VALE if given.
    subroutine project_one(cmd, f, mesh1, corr, out, st)
        type(command_t), intent(in) :: cmd
        type(field_t), intent(in) :: f
        type(mesh_t), intent(in) :: mesh1
        type(projection_concept_t), intent(in) :: corr
        type(field_t), intent(out) :: out
        type(status_t), intent(out) :: st
        logical :: has_prol
        real(dp) :: prol
        call prolongation(cmd, has_prol, prol, st)
        if (st%failed()) return
        if (has_prol) then
            call project_node_field(f, mesh1, corr%proj, out, st, prol)
        else
            call project_node_field(f, mesh1, corr%proj, out, st)
        end if
    end subroutine project_one

    ! CHAM_GD: a nodal field of the source mesh, onto the target.
    subroutine project_field_concept(ctx, cmd, corr, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(projection_concept_t), intent(in) :: corr
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        type(field_concept_t), allocatable :: out
        type(mesh_t), pointer :: mesh1
        call cmd%get_concept('CHAM_GD', p, st)
        if (st%failed()) return
        select type (p)
        type is (field_concept_t)
            call mesh_of_support(corr%source, mesh1, st)
            if (st%failed()) return
            allocate (out)
            call project_one(cmd, p%field, mesh1, corr, out%field, st)
            if (st%failed()) then
                call relocate(cmd, 'CHAM_GD', st)
                return
            end if
            out%support => corr%target
            call ctx%write_mess('    PROJ_CHAMP: field ' // p%field%quantity // ' projected')
            call move_alloc(out, result)
        class default
            call cmd%error_at('CHAM_GD', 'expected a field, got ' // p%type_name(), st)
        end select
    end subroutine project_field_concept

    ! RESULTAT: its nodal fields at the instants asked for, into a result on the target.
    subroutine project_result(ctx, cmd, corr, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(projection_concept_t), intent(in) :: corr
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        type(result_concept_t), allocatable :: out
        type(mesh_t), pointer :: mesh1, mesh2
        type(field_t), pointer :: f
        type(field_t) :: done
        type(string_t), allocatable :: names(:)
        integer, allocatable :: indices(:)
        logical :: by_inst, all_fields
        integer(i4) :: i, k, at, n_done
        call cmd%get_concept('RESULTAT', p, st)
        if (st%failed()) return
        select type (p)
        type is (result_concept_t)
            call mesh_of_support(corr%source, mesh1, st)
            if (st%ok()) call mesh_of_support(corr%target, mesh2, st)
            if (st%failed()) return
            if (p%mesh%n_nodes /= mesh1%n_nodes) then
                call cmd%error_at('RESULTAT', 'the result lives on a mesh of ' // &
                    to_text(p%mesh%n_nodes) // ' nodes, the source mesh (MODELE_1 / ' // &
                    'MAILLAGE_1) has ' // to_text(mesh1%n_nodes), st, STATUS_MODEL_ERROR)
                return
            end if
            call selected_instants(cmd, p, indices, by_inst, st)
            if (st%failed()) return
            all_fields = .not. cmd%has('NOM_CHAM')
            if (.not. all_fields) call cmd%get_texts('NOM_CHAM', names, st)
            if (st%failed()) return
            allocate (out)
            call result_fields_init(out, p%type_name(), max(size(indices), 1))
            out%mesh = mesh2
            call target_structure(corr, out)
            n_done = 0
            do i = 1, size(indices)
                call result_add_instant(out, p%nume_ordre(indices(i)), p%inst(indices(i)), at)
                if (all_fields) call nodal_fields_of(p, int(indices(i), i4), names, st)
                if (st%failed()) return
                do k = 1, size(names)
                    call result_field_at(p, int(indices(i), i4), names(k)%s, f, st)
                    if (st%ok()) call project_one(cmd, f, mesh1, corr, done, st)
                    if (st%failed()) then
                        st%message = names(k)%s // ': ' // st%message
                        call relocate(cmd, trim(merge('NOM_CHAM', 'RESULTAT', &
                            cmd%has('NOM_CHAM'))), st)
                        return
                    end if
                    call result_put_field(out, at, names(k)%s, done)
                    n_done = n_done + 1
                end do
            end do
            call ctx%write_mess('    PROJ_CHAMP: ' // to_text(n_done) // ' field(s) at ' // &
                to_text(size(indices)) // ' instant(s)')
            call move_alloc(out, result)
        class default
            call cmd%error_at('RESULTAT', 'expected a result, got ' // p%type_name(), st)
        end select
    end subroutine project_result

    ! The nodal fields a result holds at instant `at` (DEPL from an analysis's state).
    subroutine nodal_fields_of(res, at, names, st)
        type(result_concept_t), target, intent(inout) :: res
        integer(i4), intent(in) :: at
        type(string_t), allocatable, intent(out) :: names(:)
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: stored(:)
        type(field_t), pointer :: f
        integer(i4) :: k
        allocate (names(0))
        if (res%has_state) then
            call result_field_at(res, at, 'DEPL', f, st)
            if (st%failed()) return
        end if
        stored = result_stored_names(res, at)
        do k = 1, size(stored, kind=i4)
            call result_field_at(res, at, stored(k)%s, f, st)
            if (st%failed()) then
                call clear_status(st)
                cycle
            end if
            if (f%location == FIELD_NOEU) names = [names, stored(k)]
        end do
    end subroutine nodal_fields_of

    ! The result's structure: MODELE_2 when given (CALC_CHAMP and loads then see it).
    subroutine target_structure(corr, out)
        type(projection_concept_t), intent(in) :: corr
        type(result_concept_t), intent(inout) :: out
        select type (t => corr%target)
        type is (model_concept_t)
            out%model = t%model
            out%dofs = t%dofs
            out%model_name = t%name
            out%has_structure = .true.
            allocate (out%choc(t%mesh%n_cells), source=.false.)
            call material_field_init(out%materials, t%mesh)
            call cara_elem_init(out%cara, t%mesh)
        end select
    end subroutine target_structure

    ! Locates a failed status at `key` (STATUS_MODEL_ERROR unless not built).

end module proj_champ_command
