!> DEFI_GROUP (U4.22.01): new groups of cells and nodes in a mesh, and groups removed. The
!> command modifies its mesh in place (Code_Aster's reentrant operator: reuse=MAIL with
!> MAILLAGE=MAIL), so a model built on the mesh before sees the new groups.
!>
!> Order, as Code_Aster's op0104: DETR_GROUP_MA and DETR_GROUP_NO first (a name that is not
!> a group is ignored), then every CREA_GROUP_MA occurrence, then every CREA_GROUP_NO one,
!> each seeing the groups the earlier ones made. A group whose name exists already is an
!> error (destroy it first); a group that would be empty is not created, with a warning
!> (an alarm in Code_Aster; none with ALARME='NON'), so a later use of its name is "no
!> GROUP_MA named ...". The whole command works on a copy: an error leaves the mesh as it
!> was.
module mesh_group_commands
    use kinds, only: dp, i4
    use status, only: status_t
    use strings, only: string_t, to_text
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, find_cell_group, cells_of_group, n_cell_groups, &
        n_node_groups, mesh_add_cell_group, mesh_remove_node_groups, mesh_remove_cell_groups, &
        cell_name, node_name
    use mesh_name_index, only: name_find
    use mesh_concept, only: mesh_concept_t
    use mesh_geometry, only: z_constant, DEGREE
    use mesh_group_select, only: filter_cells_by_type, cells_by_node_mask, sphere_mask, axis_mask, band_mask, &
        cells_facing, criterion_code, AT_LEAST_ONE
    use mesh_group_keywords, only: read_centre, read_direction, read_positive, &
        read_named_cells, read_named_nodes, first_group_slice, report_group, fold_groups, &
        DIRECTION_AT_LEAST, &
        DIRECTION_EXACT, DIRECTION_3D
    use mesh_command_support, only: relocate_error, read_groups, all_cells, warn_at
    use mesh_node_group_commands, only: create_node_group
    implicit none
    private

    public :: run_defi_group, mesh_in_place

contains

    !> DEFI_GROUP(reuse=MAIL, MAILLAGE=MAIL, DETR_GROUP_MA, DETR_GROUP_NO, CREA_GROUP_MA,
    !> CREA_GROUP_NO, ALARME, INFO). Returns no new concept: the command's value is MAIL.
    !> The .mess gets a line per group made or removed (INFO=2: their members too).
    subroutine run_defi_group(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(mesh_concept_t), pointer :: target
        type(mesh_t) :: work
        character(len=:), allocatable :: alarm
        logical :: alarms
        integer(i4) :: i, info
        if (allocated(result)) deallocate (result)   ! in place: the value is MAIL itself
        call mesh_in_place(cmd, target, st)
        if (st%failed()) return
        call cmd%get_text('ALARME', alarm, st)
        if (st%failed()) return
        alarms = alarm == 'OUI'
        info = 1
        if (cmd%has('INFO')) then
            call cmd%get_int('INFO', info, st)
            if (st%failed()) return
        end if
        work = target%mesh
        call destroy_groups(ctx, cmd, 'DETR_GROUP_MA', work, .true.)
        call destroy_groups(ctx, cmd, 'DETR_GROUP_NO', work, .false.)
        do i = 1, cmd%count('CREA_GROUP_MA')
            call create_cell_group(ctx, cmd%occurrence('CREA_GROUP_MA', i), work, alarms, &
                                   info, st)
            if (st%failed()) return
        end do
        do i = 1, cmd%count('CREA_GROUP_NO')
            call create_node_group(ctx, cmd%occurrence('CREA_GROUP_NO', i), work, alarms, &
                                   info, st)
            if (st%failed()) return
        end do
        target%mesh = work
    end subroutine run_defi_group

    !> The mesh concept a reentrant mesh command modifies: cmd%reuse, which validation has
    !> checked is the MAILLAGE too (Code_Aster: SOUSTRUC_15, MESH1_15; the command's result is
    !> its mesh, so reuse= is required).
    !>  target : out, pointer to the concept (owned by the run context)
    !>  st     : out, at MAILLAGE: no reuse=, or not a mesh
    subroutine mesh_in_place(cmd, target, st)
        type(command_t), intent(in) :: cmd
        type(mesh_concept_t), pointer, intent(out) :: target
        type(status_t), intent(out) :: st
        target => null()
        if (.not. associated(cmd%reuse)) then
            call cmd%error_at('MAILLAGE', cmd%name // ' modifies its mesh in place: write ' // &
                'MAIL = ' // cmd%name // '(reuse=MAIL, MAILLAGE=MAIL, ...)', st)
            return
        end if
        select type (p => cmd%reuse)
        type is (mesh_concept_t)
            target => p
        class default
            call cmd%error_at('MAILLAGE', 'expected a mesh (maillage), got ' // p%type_name(), &
                              st)
        end select
    end subroutine mesh_in_place
    ! DETR_GROUP_MA / DETR_GROUP_NO: every NOM of every occurrence; names that are not groups
    ! are ignored, as in Code_Aster (detgnm).
    subroutine destroy_groups(ctx, cmd, key, mesh, cells)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        character(len=*), intent(in) :: key
        type(mesh_t), intent(inout) :: mesh
        logical, intent(in) :: cells
        type(keyword_set_t) :: occ
        type(string_t), allocatable :: names(:)
        logical, allocatable :: remove(:)
        type(status_t) :: st
        integer(i4) :: i, k, g
        if (cmd%count(key) == 0) return
        if (cells) then
            allocate (remove(n_cell_groups(mesh)), source=.false.)
        else
            allocate (remove(n_node_groups(mesh)), source=.false.)
        end if
        do i = 1, cmd%count(key)
            occ = cmd%occurrence(key, i)
            call occ%get_texts('NOM', names, st)
            if (st%failed()) cycle
            do k = 1, size(names)
                if (cells) then
                    g = name_find(mesh%cell_group_names, names(k)%s)
                else
                    g = name_find(mesh%node_group_names, names(k)%s)
                end if
                if (g > 0) then
                    if (.not. remove(g)) call ctx%write_mess('    ' // &
                        trim(merge('GROUP_MA', 'GROUP_NO', cells)) // ' ' // names(k)%s // &
                        ' removed')
                    remove(g) = .true.
                end if
            end do
        end do
        if (cells) then
            call mesh_remove_cell_groups(mesh, remove)
        else
            call mesh_remove_node_groups(mesh, remove)
        end if
    end subroutine destroy_groups

    ! One CREA_GROUP_MA occurrence.
    subroutine create_cell_group(ctx, occ, mesh, alarms, info, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(inout) :: mesh
        logical, intent(in) :: alarms
        integer(i4), intent(in) :: info
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: name, filter
        integer(i4), allocatable :: cells(:)
        call occ%get_text('NOM', name, st)
        if (st%failed()) return
        if (name_find(mesh%cell_group_names, name) > 0) then
            call occ%error_at('NOM', 'GROUP_MA ' // name // ' exists already (remove it ' // &
                'first with DETR_GROUP_MA to make it again)', st)
            return
        end if
        if (occ%has('TOUT')) then
            cells = all_cells(mesh)
        else if (occ%has('MAILLE')) then
            call read_named_cells(ctx, occ, 'MAILLE', mesh, 'GROUP_MA ' // name, cells, st)
        else if (occ%has('GROUP_MA')) then
            call first_group_slice(ctx, occ, 'GROUP_MA', mesh, .true., cells, st)
        else if (occ%has('INTERSEC')) then
            call fold_groups(occ, 'INTERSEC', mesh, .true., 'INTERSEC', cells, st)
        else if (occ%has('UNION')) then
            call fold_groups(occ, 'UNION', mesh, .true., 'UNION', cells, st)
        else if (occ%has('DIFFE')) then
            call fold_groups(occ, 'DIFFE', mesh, .true., 'DIFFE', cells, st)
        else
            call cells_of_option(ctx, occ, mesh, cells, st)
        end if
        if (st%failed()) return
        call occ%get_text('TYPE_MAILLE', filter, st)
        if (st%failed()) return
        if (filter /= 'TOUT') cells = filter_cells_by_type(mesh, cells, filter)
        if (size(cells) == 0) then
            if (alarms) call warn_at(ctx, occ, 'NOM', 'GROUP_MA ' // name // &
                ' would be empty: it is not created')
            return
        end if
        call mesh_add_cell_group(mesh, name, cells, 0_i4, st)
        if (st%failed()) then
            call relocate_error(occ, 'NOM', st)
            return
        end if
        call report_group(ctx, mesh, 'GROUP_MA', name, cells, info)
    end subroutine create_cell_group

    ! OPTION = FACE_NORMALE, SPHERE, CYLINDRE, BANDE, APPUI.
    subroutine cells_of_option(ctx, occ, mesh, cells, st)
        type(run_context_t), intent(in) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        integer(i4), allocatable, intent(out) :: cells(:)
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: option, word
        real(dp) :: x0(3), v(3), radius, angle
        integer(i4) :: ndim, criterion
        integer(i4), allocatable :: nodes(:)
        logical, allocatable :: mask(:)
        call occ%get_text('OPTION', option, st)
        if (st%failed()) return
        ndim = merge(2, 3, z_constant(mesh))
        criterion = AT_LEAST_ONE
        if (occ%has('CRIT_NOEUD')) then
            call occ%get_text('CRIT_NOEUD', word, st)
            if (st%failed()) return
            criterion = criterion_code(word)
        end if
        select case (option)
        case ('FACE_NORMALE')
            call read_direction(occ, ndim, DIRECTION_AT_LEAST, option, v, st)
            if (st%failed()) return
            call occ%get_real('ANGL_PREC', angle, st)
            if (st%failed()) return
            call occ%get_text('VERI_SIGNE', word, st)
            if (st%failed()) return
            cells = cells_facing(mesh, v, angle * DEGREE, word == 'OUI', mesh%dim == 2)
        case ('SPHERE')
            call read_centre(ctx, occ, mesh, ndim, x0, st)
            if (st%ok()) call read_positive(occ, 'RAYON', radius, st)
            if (st%failed()) return
            cells = cells_by_node_mask(mesh, sphere_mask(mesh, x0, radius, ndim), criterion)
        case ('CYLINDRE')
            call read_direction(occ, ndim, DIRECTION_3D, option, v, st)
            if (st%ok()) call read_centre(ctx, occ, mesh, ndim, x0, st)
            if (st%ok()) call read_positive(occ, 'RAYON', radius, st)
            if (st%failed()) return
            cells = cells_by_node_mask(mesh, axis_mask(mesh, x0, v, radius), criterion)
        case ('BANDE')
            call read_centre(ctx, occ, mesh, ndim, x0, st)
            if (st%ok()) call read_positive(occ, 'DIST', radius, st)
            if (st%ok()) call read_direction(occ, ndim, DIRECTION_EXACT, option, v, st)
            if (st%failed()) return
            cells = cells_by_node_mask(mesh, band_mask(mesh, x0, v, radius, ndim), criterion)
        case default   ! APPUI
            if (occ%has('NOEUD')) then
                call read_named_nodes(ctx, occ, 'NOEUD', mesh, 'OPTION APPUI', nodes, st)
                if (st%failed()) return
            else
                call fold_groups(occ, 'GROUP_NO', mesh, .false., 'UNION', nodes, st)
                if (st%failed()) return
            end if
            call occ%get_text('TYPE_APPUI', word, st)
            if (st%failed()) return
            allocate (mask(mesh%n_nodes), source=.false.)
            mask(nodes) = .true.
            cells = cells_by_node_mask(mesh, mask, criterion_code(word))
        end select
    end subroutine cells_of_option

end module mesh_group_commands
