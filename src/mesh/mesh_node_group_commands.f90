!> DEFI_GROUP/CREA_GROUP_NO (U4.22.01): one occurrence makes one or several node groups.
!>  - TOUT_GROUP_MA='OUI': a GROUP_NO of the same name for every GROUP_MA (its nodes);
!>  - GROUP_MA=(g1, g2, ...): one GROUP_NO per group (named NOM(i), or like the GROUP_MA), or
!>    with a single NOM their union; CRIT_NOEUD chooses vertices, mid-edge or centre nodes;
!>  - NOEUD, GROUP_NO (its first group, NUME_INIT/NUME_FIN/POSITION), INTERSEC, UNION,
!>    DIFFE of node groups;
!>  - OPTION: ENV_SPHERE, ENV_CYLINDRE, PLAN, SEGM_DROI_ORDO, NOEUD_ORDO, INCLUSION.
!> Nodes of cells come in increasing node number (Code_Aster's gmgnre), set operations in
!> utlisi's order, ordered options in their order (mesh_node_path).
module mesh_node_group_commands
    use kinds, only: dp, i4
    use status, only: status_t
    use strings, only: string_t, to_text
    use deck_command, only: keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, cells_of_group, nodes_of_group, n_cell_groups, &
        cell_group_name, mesh_add_node_group, node_name
    use mesh_name_index, only: name_find
    use mesh_concept, only: mesh_concept_t
    use deck_concept, only: concept_t
    use mesh_cell_kinds, only: ROLE_ALL, ROLE_VERTEX, ROLE_MID_EDGE, ROLE_CENTRE
    use mesh_geometry, only: z_constant
    use mesh_group_select, only: ordered_union, ordered_intersection, ordered_difference, &
        nodes_of_cells_by_role, nodes_on_sphere, nodes_on_cylinder, nodes_on_plane, &
        min_edge_length
    use mesh_group_keywords, only: read_centre, read_direction, read_positive, &
        read_named_nodes, first_group_slice, report_group, fold_groups, DIRECTION_EXACT, &
        DIRECTION_3D
    use mesh_node_path, only: order_line_nodes, order_segment_nodes
    use mesh_inclusion, only: nodes_in_cells, INCLUSION_2D, INCLUSION_SURFACE
    use mesh_command_support, only: relocate_error, read_groups, read_node_groups, warn_at, &
        group_first_node
    implicit none
    private

    public :: create_node_group

contains

    !> One CREA_GROUP_NO occurrence on `mesh` (the work copy of DEFI_GROUP).
    !>  alarms : ALARME='OUI' (warn of a group that would be empty);  info : INFO
    !>  st : out, located at the keyword at fault
    subroutine create_node_group(ctx, occ, mesh, alarms, info, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(inout) :: mesh
        logical, intent(in) :: alarms
        integer(i4), intent(in) :: info
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: name
        integer(i4), allocatable :: nodes(:)
        if (occ%has('TOUT_GROUP_MA')) then
            call from_every_cell_group(ctx, occ, mesh, alarms, info, st)
            return
        end if
        if (occ%has('GROUP_MA') .and. .not. occ%has('OPTION')) then
            call from_cell_groups(ctx, occ, mesh, alarms, info, st)
            return
        end if
        call occ%get_text('NOM', name, st)
        if (st%failed()) return
        if (name_find(mesh%node_group_names, name) > 0) then
            call occ%error_at('NOM', already(name), st)
            return
        end if
        if (occ%has('OPTION')) then
            call nodes_of_option(ctx, occ, mesh, nodes, st)
        else if (occ%has('NOEUD')) then
            call read_named_nodes(ctx, occ, 'NOEUD', mesh, 'GROUP_NO ' // name, nodes, st)
        else if (occ%has('GROUP_NO')) then
            call first_group_slice(ctx, occ, 'GROUP_NO', mesh, .false., nodes, st)
        else if (occ%has('INTERSEC')) then
            call fold_groups(occ, 'INTERSEC', mesh, .false., 'INTERSEC', nodes, st)
        else if (occ%has('UNION')) then
            call fold_groups(occ, 'UNION', mesh, .false., 'UNION', nodes, st)
        else
            call fold_groups(occ, 'DIFFE', mesh, .false., 'DIFFE', nodes, st)
        end if
        if (st%failed()) return
        call add_node_group(ctx, occ, 'NOM', mesh, name, nodes, alarms, info, st)
    end subroutine create_node_group

    ! "GROUP_NO X exists already ..." (SOUSTRUC_37).
    function already(name) result(text)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: text
        text = 'GROUP_NO ' // name // ' exists already (remove it first with DETR_GROUP_NO ' // &
               'to make it again)'
    end function already

    ! Adds the group, or warns that it would be empty (SOUSTRUC_38) and adds nothing.
    subroutine add_node_group(ctx, occ, key, mesh, name, nodes, alarms, info, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key, name
        type(mesh_t), intent(inout) :: mesh
        integer(i4), intent(in) :: nodes(:), info
        logical, intent(in) :: alarms
        type(status_t), intent(out) :: st
        if (size(nodes) == 0) then
            if (alarms) call warn_at(ctx, occ, key, 'GROUP_NO ' // name // &
                                     ' would be empty: it is not created')
            return
        end if
        call mesh_add_node_group(mesh, name, nodes, 0_i4, st)
        if (st%failed()) then
            call relocate_error(occ, key, st)
            return
        end if
        call report_group(ctx, mesh, 'GROUP_NO', name, nodes, info)
    end subroutine add_node_group

    ! TOUT_GROUP_MA='OUI': for every GROUP_MA (those of this command's CREA_GROUP_MA too),
    ! the GROUP_NO of its nodes, under the same name.
    subroutine from_every_cell_group(ctx, occ, mesh, alarms, info, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(inout) :: mesh
        logical, intent(in) :: alarms
        integer(i4), intent(in) :: info
        type(status_t), intent(out) :: st
        integer(i4) :: g, n
        character(len=:), allocatable :: name
        n = n_cell_groups(mesh)
        do g = 1, n
            name = cell_group_name(mesh, g)
            if (name_find(mesh%node_group_names, name) > 0) then
                call occ%error_at('TOUT_GROUP_MA', already(name) // ': it is the name of ' // &
                                  'GROUP_MA ' // name, st)
                return
            end if
            call add_node_group(ctx, occ, 'TOUT_GROUP_MA', mesh, name, &
                nodes_of_cells_by_role(mesh, cells_of_group(mesh, g), ROLE_ALL), alarms, &
                info, st)
            if (st%failed()) return
        end do
    end subroutine from_every_cell_group

    ! GROUP_MA=(...) with NOM (none, one, or one per group) and CRIT_NOEUD.
    subroutine from_cell_groups(ctx, occ, mesh, alarms, info, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(inout) :: mesh
        logical, intent(in) :: alarms
        integer(i4), intent(in) :: info
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: groups_names(:), names(:)
        integer(i4), allocatable :: groups(:), nodes(:), merged(:)
        character(len=:), allocatable :: word
        integer(i4) :: g, role
        character(len=:), allocatable :: key
        call read_groups(occ, 'GROUP_MA', mesh, groups_names, groups, st)
        if (st%failed()) return
        if (occ%has('NOM')) then
            call occ%get_texts('NOM', names, st)
            if (st%failed()) return
            key = 'NOM'
            if (size(names) /= 1 .and. size(names) /= size(groups)) then
                call occ%error_at('NOM', 'give one name per GROUP_MA (' // &
                    to_text(size(groups, kind=i4)) // '), or one name for the union of ' // &
                    'their nodes (got ' // to_text(size(names, kind=i4)) // ')', st)
                return
            end if
        else
            names = groups_names
            key = 'GROUP_MA'
        end if
        call occ%get_text('CRIT_NOEUD', word, st)
        if (st%failed()) return
        select case (word)
        case ('SOMMET')
            role = ROLE_VERTEX
        case ('MILIEU')
            role = ROLE_MID_EDGE
        case ('CENTRE')
            role = ROLE_CENTRE
        case default
            role = ROLE_ALL
        end select
        do g = 1, size(names, kind=i4)
            if (name_find(mesh%node_group_names, names(g)%s) > 0) then
                call occ%error_at(key, already(names(g)%s), st)
                return
            end if
        end do
        if (size(names) == 1 .and. size(groups) > 1) then
            allocate (merged(0))
            do g = 1, size(groups, kind=i4)
                nodes = nodes_of_cells_by_role(mesh, cells_of_group(mesh, groups(g)), role)
                merged = ordered_union(merged, nodes, mesh%n_nodes)
            end do
            call add_node_group(ctx, occ, key, mesh, names(1)%s, merged, alarms, info, st)
            return
        end if
        do g = 1, size(groups, kind=i4)
            nodes = nodes_of_cells_by_role(mesh, cells_of_group(mesh, groups(g)), role)
            call add_node_group(ctx, occ, key, mesh, names(g)%s, nodes, alarms, info, st)
            if (st%failed()) return
        end do
    end subroutine from_cell_groups

    ! OPTION = ENV_SPHERE, ENV_CYLINDRE, PLAN, SEGM_DROI_ORDO, NOEUD_ORDO, INCLUSION.
    subroutine nodes_of_option(ctx, occ, mesh, nodes, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        integer(i4), allocatable, intent(out) :: nodes(:)
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: option
        real(dp) :: x0(3), v(3), radius, precision
        integer(i4) :: ndim
        call occ%get_text('OPTION', option, st)
        if (st%failed()) return
        ndim = merge(2, 3, z_constant(mesh))
        select case (option)
        case ('ENV_SPHERE')
            call read_centre(ctx, occ, mesh, ndim, x0, st)
            if (st%ok()) call read_positive(occ, 'RAYON', radius, st)
            if (st%ok()) call read_positive(occ, 'PRECISION', precision, st)
            if (st%failed()) return
            nodes = nodes_on_sphere(mesh, x0, radius, precision, ndim)
        case ('ENV_CYLINDRE')
            call read_direction(occ, ndim, DIRECTION_3D, option, v, st)
            if (st%ok()) call read_centre(ctx, occ, mesh, ndim, x0, st)
            if (st%ok()) call read_positive(occ, 'RAYON', radius, st)
            if (st%ok()) call read_positive(occ, 'PRECISION', precision, st)
            if (st%failed()) return
            nodes = nodes_on_cylinder(mesh, x0, v, radius, precision)
        case ('PLAN')
            call read_centre(ctx, occ, mesh, ndim, x0, st)
            if (st%ok()) call read_direction(occ, ndim, DIRECTION_EXACT, option, v, st)
            if (st%ok()) call read_positive(occ, 'PRECISION', precision, st)
            if (st%failed()) return
            nodes = nodes_on_plane(mesh, x0, v, precision, ndim)
        case ('SEGM_DROI_ORDO')
            call segment_nodes(ctx, occ, mesh, nodes, st)
        case ('NOEUD_ORDO')
            call line_nodes(ctx, occ, mesh, nodes, st)
        case default   ! INCLUSION
            call included_nodes(occ, mesh, nodes, st)
        end select
    end subroutine nodes_of_option

    ! SEGM_DROI_ORDO: the nodes of GROUP_NO sorted along GROUP_NO_ORIG -> GROUP_NO_EXTR.
    subroutine segment_nodes(ctx, occ, mesh, nodes, st)
        type(run_context_t), intent(in) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        integer(i4), allocatable, intent(out) :: nodes(:)
        type(status_t), intent(out) :: st
        integer(i4) :: origin, extremity
        real(dp) :: precision
        character(len=:), allocatable :: criterion
        if (.not. occ%has('GROUP_NO')) then
            call occ%error_at('OPTION', 'OPTION=''SEGM_DROI_ORDO'' orders the nodes of ' // &
                              'GROUP_NO: give it', st)
            return
        end if
        call fold_groups(occ, 'GROUP_NO', mesh, .false., 'UNION', nodes, st)
        if (st%failed()) return
        call group_first_node(ctx, occ, 'GROUP_NO_ORIG', mesh, origin, st)
        if (st%ok()) call group_first_node(ctx, occ, 'GROUP_NO_EXTR', mesh, extremity, st)
        if (st%ok()) call read_positive(occ, 'PRECISION', precision, st)
        if (st%ok()) call occ%get_text('CRITERE', criterion, st)
        if (st%failed()) return
        call order_segment_nodes(mesh, nodes, origin, extremity, precision, &
                                 criterion == 'RELATIF', st)
        if (st%failed()) call relocate_error(occ, 'GROUP_NO', st)
    end subroutine segment_nodes

    ! NOEUD_ORDO: the nodes of the line of GROUP_MA in order from its origin.
    subroutine line_nodes(ctx, occ, mesh, nodes, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        integer(i4), allocatable, intent(out) :: nodes(:)
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: cells(:)
        integer(i4) :: origin, extremity, chosen
        real(dp) :: orientation(3)
        real(dp), allocatable :: values(:)
        call fold_groups(occ, 'GROUP_MA', mesh, .true., 'UNION', cells, st)
        if (st%failed()) return
        origin = 0
        extremity = 0
        if (occ%has('GROUP_NO_ORIG')) then
            call group_first_node(ctx, occ, 'GROUP_NO_ORIG', mesh, origin, st)
            if (st%failed()) return
        end if
        if (occ%has('GROUP_NO_EXTR')) then
            call group_first_node(ctx, occ, 'GROUP_NO_EXTR', mesh, extremity, st)
            if (st%failed()) return
        end if
        orientation = 0.0_dp
        if (occ%has('VECT_ORIE')) then
            call occ%get_reals('VECT_ORIE', values, st)
            if (st%failed()) return
            orientation(1:size(values)) = values
        else if (origin > 0 .and. origin == extremity) then
            call warn_at(ctx, occ, 'GROUP_NO_EXTR', 'the line is closed (GROUP_NO_ORIG = ' // &
                'GROUP_NO_EXTR): without VECT_ORIE its sense is that of its first cell')
        end if
        call order_line_nodes(mesh, cells, origin, extremity, occ%has('ORIGINE'), &
                              orientation, nodes, chosen, st)
        if (st%failed()) then
            call relocate_error(occ, 'GROUP_MA', st)
            return
        end if
        if (origin == 0) call ctx%write_mess('    NOEUD_ORDO: the line starts at node ' // &
                                             node_name(mesh, chosen))
    end subroutine line_nodes

    ! INCLUSION: the nodes of GROUP_MA's cells lying in the cells of GROUP_MA_INCL (of
    ! MAILLAGE_INCL, else of this mesh), within DISTANCE_MAX (default: 1 % of the mesh's
    ! shortest edge, Code_Aster's 0.01 AR_MIN).
    subroutine included_nodes(occ, mesh, nodes, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in), target :: mesh
        integer(i4), allocatable, intent(out) :: nodes(:)
        type(status_t), intent(out) :: st
        type(mesh_t), pointer :: other
        class(concept_t), pointer :: p
        integer(i4), allocatable :: cells(:), incl(:)
        character(len=:), allocatable :: case_word
        real(dp) :: distance
        integer(i4) :: mode
        other => mesh
        if (occ%has('MAILLAGE_INCL')) then
            call occ%get_concept('MAILLAGE_INCL', p, st)
            if (st%failed()) return
            select type (p)
            type is (mesh_concept_t)
                other => p%mesh
            class default
                call occ%error_at('MAILLAGE_INCL', 'expected a mesh, got ' // p%type_name(), st)
                return
            end select
        end if
        call fold_groups(occ, 'GROUP_MA', mesh, .true., 'UNION', cells, st)
        if (st%ok()) call fold_groups(occ, 'GROUP_MA_INCL', other, .true., 'UNION', incl, st)
        if (st%failed()) return
        call occ%get_text('CAS_FIGURE', case_word, st)
        if (st%failed()) return
        select case (case_word)
        case ('2D')
            mode = INCLUSION_2D
        case ('2.5D')
            mode = INCLUSION_SURFACE
        case default
            call occ%error_at('CAS_FIGURE', 'CAS_FIGURE=''3D'' projects on volume cells, ' // &
                'which parasol meshes do not have (2D: plane cells; 2.5D: surface cells ' // &
                'in space)', st)
            return
        end select
        if (occ%has('DISTANCE_MAX')) then
            call read_positive(occ, 'DISTANCE_MAX', distance, st)
            if (st%failed()) return
        else
            distance = 0.01_dp * min_edge_length(mesh)
        end if
        call nodes_in_cells(mesh, nodes_of_cells_by_role(mesh, cells, ROLE_ALL), other, incl, &
                            distance, mode, nodes, st)
        if (st%failed()) call relocate_error(occ, 'GROUP_MA_INCL', st)
    end subroutine included_nodes

end module mesh_node_group_commands
