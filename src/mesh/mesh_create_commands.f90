!> CREA_MAILLAGE (U4.23.02): a new mesh made from MAILLAGE by one operation (Code_Aster's
!> UN_PARMI): CREA_POI1, CREA_MAILLE, MODI_MAILLE (QUAD_TRIA3, QUAD8_9), LINE_QUAD,
!> QUAD_LINE, RESTREINT (mesh_restrict). The geometry of each operation is in mesh_create; this module reads the
!> keywords as Code_Aster does (op0167): the cells and nodes an occurrence names come in
!> increasing number, each once; a selection that names nothing is an error; a new group
!> named like an existing one is an error (MESH1_20); converting only part of a mesh is
!> allowed with Code_Aster's warning (MESH1_4: the mesh may not be conforming).
module mesh_create_commands
    use kinds, only: i4
    use status, only: status_t, STATUS_NOT_IMPLEMENTED
    use strings, only: string_t, to_text
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, mesh_summary, cells_of_group, nodes_of_group, &
        n_cell_groups, n_node_groups
    use mesh_name_index, only: name_find
    use mesh_concept, only: mesh_concept_t
    use mesh_cell_shapes, only: CELL_TRIA6, CELL_QUAD8
    use mesh_group_select, only: nodes_of_cells_by_role
    use mesh_cell_kinds, only: ROLE_ALL
    use mesh_group_keywords, only: read_named_cells, read_named_nodes, fold_groups
    use mesh_create, only: add_point_cells, duplicate_cells, split_quadrangles, &
        add_face_centres, to_quadratic, to_linear
    use mesh_command_support, only: relocate_error, warn_at, read_groups, read_node_groups
    use mesh_restrict, only: restrict_mesh
    implicit none
    private

    public :: run_crea_maillage

contains

    !> CREA_MAILLAGE(MAILLAGE, one of CREA_POI1, CREA_MAILLE, MODI_MAILLE, LINE_QUAD,
    !> QUAD_LINE, RESTREINT). The .mess gets what was made and the new mesh's summary.
    subroutine run_crea_maillage(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        type(mesh_concept_t), allocatable :: made
        character(len=100), allocatable :: lines(:)
        integer(i4) :: k
        call cmd%get_concept('MAILLAGE', p, st)
        if (st%failed()) return
        allocate (made)
        select type (p)
        type is (mesh_concept_t)
            if (cmd%count('CREA_POI1') > 0) then
                call crea_poi1(ctx, cmd, p%mesh, made%mesh, st)
            else if (cmd%count('CREA_MAILLE') > 0) then
                call crea_maille(ctx, cmd, p%mesh, made%mesh, st)
            else if (cmd%count('MODI_MAILLE') > 0) then
                call modi_maille(ctx, cmd, p%mesh, made%mesh, st)
            else if (cmd%count('LINE_QUAD') > 0) then
                call convert_degree(ctx, cmd, 'LINE_QUAD', p%mesh, made%mesh, st)
            else if (cmd%count('RESTREINT') > 0) then
                call restreint(ctx, cmd, p%mesh, made%mesh, st)
            else
                call convert_degree(ctx, cmd, 'QUAD_LINE', p%mesh, made%mesh, st)
            end if
        class default
            call cmd%error_at('MAILLAGE', 'expected a mesh (maillage), got ' // p%type_name(), &
                              st)
        end select
        if (st%failed()) return
        if (cmd%has('TITRE')) call cmd%get_text('TITRE', made%mesh%title, st)
        lines = mesh_summary(made%mesh)
        do k = 1, size(lines)
            call ctx%write_mess('    ' // trim(lines(k)))
        end do
        call move_alloc(made, result)
    end subroutine run_crea_maillage

    ! CREA_POI1: the nodes of each occurrence (TOUT, GROUP_MA, GROUP_NO, NOEUD: their union).
    subroutine crea_poi1(ctx, cmd, mesh, out, st)
        type(run_context_t), intent(in) :: ctx
        type(command_t), intent(in) :: cmd
        type(mesh_t), intent(in) :: mesh
        type(mesh_t), intent(out) :: out
        type(status_t), intent(out) :: st
        type(keyword_set_t) :: occ
        logical, allocatable :: chosen(:, :)
        character(len=:), allocatable :: names(:)
        type(string_t), allocatable :: given(:)
        integer(i4), allocatable :: list(:)
        integer(i4) :: o, n, longest
        n = cmd%count('CREA_POI1')
        allocate (chosen(mesh%n_nodes, n), source=.false.)
        longest = 1
        do o = 1, n
            occ = cmd%occurrence('CREA_POI1', o)
            if (occ%has('NOM_GROUP_MA')) then
                call occ%get_texts('NOM_GROUP_MA', given, st)
                if (st%failed()) return
                longest = max(longest, len(given(1)%s))
            end if
        end do
        allocate (character(len=longest) :: names(n))
        names = ''
        do o = 1, n
            occ = cmd%occurrence('CREA_POI1', o)
            if (occ%has('TOUT')) chosen(:, o) = .true.
            if (occ%has('GROUP_MA')) then
                call fold_groups(occ, 'GROUP_MA', mesh, .true., 'UNION', list, st)
                if (st%failed()) return
                chosen(nodes_of_cells_by_role(mesh, list, ROLE_ALL), o) = .true.
            end if
            if (occ%has('GROUP_NO')) then
                call fold_groups(occ, 'GROUP_NO', mesh, .false., 'UNION', list, st)
                if (st%failed()) return
                chosen(list, o) = .true.
            end if
            if (occ%has('NOEUD')) then
                call read_named_nodes(ctx, occ, 'NOEUD', mesh, 'CREA_POI1', list, st)
                if (st%failed()) return
                chosen(list, o) = .true.
            end if
            if (.not. any(chosen(:, o))) then
                call occ%error_at('', 'the occurrence names no node', st)
                return
            end if
            if (.not. occ%has('NOM_GROUP_MA')) cycle
            call occ%get_texts('NOM_GROUP_MA', given, st)
            if (st%failed()) return
            if (size(given) > 1) call warn_at(ctx, occ, 'NOM_GROUP_MA', 'only the first ' // &
                'name, ' // given(1)%s // ', is used (as in Code_Aster)')
            call check_new_group(occ, 'NOM_GROUP_MA', mesh, given(1)%s, names(1:o - 1), st)
            if (st%failed()) return
            names(o) = given(1)%s
        end do
        call add_point_cells(mesh, chosen, names, out, st)
        if (st%failed()) call relocate_error(cmd, 'CREA_POI1', st)
        call ctx%write_mess('    CREA_POI1: ' // to_text(out%n_cells - mesh%n_cells) // &
                            ' POI1 cells made')
    end subroutine crea_poi1

    ! RESTREINT=_F(GROUP_MA, TOUT_GROUP_MA, GROUP_NO, TOUT_GROUP_NO): the cells of the
    ! GROUP_MA groups, the nodes of those cells and of the GROUP_NO groups; the groups kept
    ! are the GROUP_MA (TOUT_GROUP_MA='OUI': every cell group) and the GROUP_NO (TOUT_GROUP_NO
    ! ='OUI': every node group), reduced to what is kept (mesh_restrict, as rdtmai).
    subroutine restreint(ctx, cmd, mesh, out, st)
        type(run_context_t), intent(in) :: ctx
        type(command_t), intent(in) :: cmd
        type(mesh_t), intent(in) :: mesh
        type(mesh_t), intent(out) :: out
        type(status_t), intent(out) :: st
        type(keyword_set_t) :: occ
        type(string_t), allocatable :: names(:)
        integer(i4), allocatable :: cell_groups(:), node_groups(:), list(:), cells(:), &
            nodes(:)
        character(len=:), allocatable :: every_ma, every_no
        logical, allocatable :: mark(:)
        integer(i4) :: g, made_ma, made_no
        occ = cmd%occurrence('RESTREINT', 1)
        call read_groups(occ, 'GROUP_MA', mesh, names, cell_groups, st)
        if (st%failed()) return
        allocate (mark(mesh%n_cells), source=.false.)
        do g = 1, size(cell_groups, kind=i4)
            list = cells_of_group(mesh, cell_groups(g))
            mark(list) = .true.
        end do
        cells = pack([(g, g = 1, mesh%n_cells)], mark)
        if (size(cells) == 0) then
            call occ%error_at('GROUP_MA', 'the groups hold no cell: the mesh would be ' // &
                              'empty', st)
            return
        end if
        deallocate (mark)
        allocate (mark(mesh%n_nodes), source=.false.)
        allocate (node_groups(0))
        if (occ%has('GROUP_NO')) then
            call read_node_groups(occ, 'GROUP_NO', mesh, names, node_groups, st)
            if (st%failed()) return
            do g = 1, size(node_groups, kind=i4)
                list = nodes_of_group(mesh, node_groups(g))
                mark(list) = .true.
            end do
        end if
        nodes = pack([(g, g = 1, mesh%n_nodes)], mark)
        call occ%get_text('TOUT_GROUP_MA', every_ma, st)
        if (st%ok()) call occ%get_text('TOUT_GROUP_NO', every_no, st)
        if (st%failed()) return
        if (every_ma == 'OUI') cell_groups = [(g, g = 1, n_cell_groups(mesh))]
        if (every_no == 'OUI') node_groups = [(g, g = 1, n_node_groups(mesh))]
        call restrict_mesh(mesh, cells, nodes, cell_groups, node_groups, out, made_ma, &
                           made_no, st)
        if (st%failed()) then
            call relocate_error(cmd, 'RESTREINT', st)
            return
        end if
        call ctx%write_mess('    RESTREINT: ' // to_text(out%n_cells) // ' of ' // &
            to_text(mesh%n_cells) // ' cells, ' // to_text(out%n_nodes) // ' of ' // &
            to_text(mesh%n_nodes) // ' nodes kept; ' // to_text(made_ma) // ' GROUP_MA, ' // &
            to_text(made_no) // ' GROUP_NO (a group left empty is not made)')
    end subroutine restreint

    ! CREA_MAILLE: copies of the cells of each occurrence (TOUT, the default, or GROUP_MA).
    subroutine crea_maille(ctx, cmd, mesh, out, st)
        type(run_context_t), intent(in) :: ctx
        type(command_t), intent(in) :: cmd
        type(mesh_t), intent(in) :: mesh
        type(mesh_t), intent(out) :: out
        type(status_t), intent(out) :: st
        type(keyword_set_t) :: occ
        integer(i4), allocatable :: cells(:), list(:), ptr(:)
        character(len=:), allocatable :: names(:), name
        integer(i4) :: o, n, longest
        n = cmd%count('CREA_MAILLE')
        allocate (ptr(n + 1), cells(0))
        ptr(1) = 1
        longest = 1
        do o = 1, n
            occ = cmd%occurrence('CREA_MAILLE', o)
            call occ%get_text('NOM', name, st)
            if (st%failed()) return
            longest = max(longest, len(name))
        end do
        allocate (character(len=longest) :: names(n))
        names = ''
        do o = 1, n
            occ = cmd%occurrence('CREA_MAILLE', o)
            call occ%get_text('NOM', name, st)
            if (st%ok()) call check_new_group(occ, 'NOM', mesh, name, names(1:o - 1), st)
            if (st%failed()) return
            names(o) = name
            call selected_cells(ctx, occ, mesh, list, st)
            if (st%failed()) return
            cells = [cells, list]
            ptr(o + 1) = size(cells, kind=i4) + 1
        end do
        call duplicate_cells(mesh, cells, ptr, names, out, st)
        if (st%failed()) call relocate_error(cmd, 'CREA_MAILLE', st)
    end subroutine crea_maille

    ! MODI_MAILLE: QUAD_TRIA3 (one occurrence; the others are then not done, as in
    ! Code_Aster) or QUAD8_9 occurrences.
    subroutine modi_maille(ctx, cmd, mesh, out, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(mesh_t), intent(in) :: mesh
        type(mesh_t), intent(out) :: out
        type(status_t), intent(out) :: st
        type(keyword_set_t) :: occ
        character(len=:), allocatable :: option
        integer(i4), allocatable :: list(:), cells(:)
        logical, allocatable :: chosen(:)
        integer(i4) :: o, n, quad_tria, done
        n = cmd%count('MODI_MAILLE')
        quad_tria = 0
        do o = 1, n
            occ = cmd%occurrence('MODI_MAILLE', o)
            call occ%get_text('OPTION', option, st)
            if (st%failed()) return
            select case (option)
            case ('QUAD_TRIA3')
                if (quad_tria > 0) then
                    call occ%error_at('OPTION', 'QUAD_TRIA3 is done by one occurrence only ' // &
                                      '(put its cells together)', st)
                    return
                end if
                quad_tria = o
            case ('TRIA6_7', 'SEG3_4')
                call occ%error_at('OPTION', 'OPTION=''' // option // ''' makes ' // &
                    trim(merge('TRIA7', 'SEG4 ', option == 'TRIA6_7')) // ' cells, which parasol ' // &
                    'does not have (it has SEG2, SEG3, TRIA3, TRIA6, QUAD4, QUAD8, QUAD9)', st, &
                    code=STATUS_NOT_IMPLEMENTED)
                return
            end select
        end do
        if (quad_tria > 0) then
            occ = cmd%occurrence('MODI_MAILLE', quad_tria)
            if (n > 1) call warn_at(ctx, occ, 'OPTION', 'with QUAD_TRIA3 the other ' // &
                'MODI_MAILLE occurrences are not done (as in Code_Aster)')
            call selected_cells(ctx, occ, mesh, list, st)
            if (st%failed()) return
            if (any(mesh%cell_type(1:mesh%n_cells) == CELL_TRIA6)) call warn_at(ctx, occ, &
                'OPTION', 'the mesh has TRIA6 cells: splitting quadrangles into TRIA3 may ' // &
                'leave it not conforming')
            if (size(list) /= mesh%n_cells) call partial_warning(ctx, occ, 'MODI_MAILLE')
            allocate (chosen(mesh%n_cells), source=.false.)
            chosen(list) = .true.
            call split_quadrangles(mesh, chosen, out, done, st)
            if (st%failed()) then
                call relocate_error(occ, 'OPTION', st)
                return
            end if
            call ctx%write_mess('    QUAD_TRIA3: ' // to_text(done) // ' quadrangles split')
            return
        end if
        allocate (cells(0))
        do o = 1, n
            occ = cmd%occurrence('MODI_MAILLE', o)
            call selected_cells(ctx, occ, mesh, list, st)
            if (st%failed()) return
            list = pack(list, mesh%cell_type(list) == CELL_QUAD8)
            if (size(list) == 0) call warn_at(ctx, occ, 'OPTION', 'no QUAD8 cell to turn ' // &
                                              'into QUAD9 among the cells named')
            cells = [cells, list]
        end do
        call add_face_centres(mesh, cells, out, done, st)
        if (st%failed()) then
            call relocate_error(cmd, 'MODI_MAILLE', st)
            return
        end if
        call ctx%write_mess('    QUAD8_9: ' // to_text(done) // ' QUAD8 made QUAD9')
    end subroutine modi_maille

    ! LINE_QUAD / QUAD_LINE on TOUT (the default) or GROUP_MA.
    subroutine convert_degree(ctx, cmd, key, mesh, out, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        character(len=*), intent(in) :: key
        type(mesh_t), intent(in) :: mesh
        type(mesh_t), intent(out) :: out
        type(status_t), intent(out) :: st
        type(keyword_set_t) :: occ
        integer(i4), allocatable :: list(:)
        logical, allocatable :: chosen(:)
        integer(i4) :: done, removed
        occ = cmd%occurrence(key, 1)
        call selected_cells(ctx, occ, mesh, list, st)
        if (st%failed()) return
        if (size(list) /= mesh%n_cells) call partial_warning(ctx, occ, key)
        allocate (chosen(mesh%n_cells), source=.false.)
        chosen(list) = .true.
        if (key == 'LINE_QUAD') then
            call to_quadratic(mesh, chosen, out, done, st)
            if (st%ok()) call ctx%write_mess('    LINE_QUAD: ' // to_text(done) // &
                ' cells made quadratic, ' // to_text(out%n_nodes - mesh%n_nodes) // ' nodes added')
        else
            call to_linear(mesh, chosen, out, done, removed, st)
            if (st%ok()) call ctx%write_mess('    QUAD_LINE: ' // to_text(done) // &
                ' cells made linear, ' // to_text(removed) // ' nodes removed')
        end if
        if (st%failed()) call relocate_error(cmd, key, st)
    end subroutine convert_degree

    ! The cells of an occurrence: TOUT (also when neither TOUT nor GROUP_MA is given:
    ! Code_Aster's UN_PARMI(TOUT, GROUP_MA, TOUT='OUI')), MAILLE, GROUP_MA; each once, in
    ! increasing number (getelem).
    subroutine selected_cells(ctx, occ, mesh, cells, st)
        type(run_context_t), intent(in) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        integer(i4), allocatable, intent(out) :: cells(:)
        type(status_t), intent(out) :: st
        logical, allocatable :: chosen(:)
        integer(i4), allocatable :: list(:)
        integer(i4) :: c
        allocate (chosen(mesh%n_cells), source=.false.)
        if (occ%has('TOUT') .or. .not. (occ%has('GROUP_MA') .or. occ%has('MAILLE'))) &
            chosen = .true.
        if (occ%has('GROUP_MA')) then
            call fold_groups(occ, 'GROUP_MA', mesh, .true., 'UNION', list, st)
            if (st%failed()) return
            chosen(list) = .true.
        end if
        if (occ%has('MAILLE')) then
            call read_named_cells(ctx, occ, 'MAILLE', mesh, '', list, st, quiet=.true.)
            if (st%failed()) return
            chosen(list) = .true.
        end if
        cells = pack([(c, c = 1, mesh%n_cells)], chosen)
    end subroutine selected_cells

    ! A new GROUP_MA name: not a group of the mesh (MESH1_20), not made twice.
    subroutine check_new_group(occ, key, mesh, name, earlier, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key, name
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: earlier(:)
        type(status_t), intent(out) :: st
        if (name_find(mesh%cell_group_names, name) > 0) then
            call occ%error_at(key, 'GROUP_MA ' // name // ' exists already in the mesh ' // &
                '(remove it first with DEFI_GROUP/DETR_GROUP_MA)', st)
        else if (any(earlier == name)) then
            call occ%error_at(key, 'GROUP_MA ' // name // ' is made by an earlier occurrence', &
                              st)
        end if
    end subroutine check_new_group

    ! MESH1_4: only part of the mesh converted.
    subroutine partial_warning(ctx, occ, key)
        type(run_context_t), intent(in) :: ctx
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        call warn_at(ctx, occ, '', key // ' changes only part of the mesh: the result may ' // &
                     'not be conforming')
    end subroutine partial_warning

end module mesh_create_commands
