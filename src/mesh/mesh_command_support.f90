!> Helpers shared by the command handlers of the mesh and model layers: locating an error
!> found by a lower layer at the deck keyword it concerns, turning GROUP_MA / GROUP_NO / TOUT
!> keywords into cell and node lists with errors located at the keyword, and located
!> warnings (Code_Aster's alarms).
module mesh_command_support
    use kinds, only: i4
    use status, only: status_t, format_status
    use strings, only: string_t, to_text
    use deck_command, only: keyword_set_t
    use keyword_relocation, only: relocate_error
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, find_cell_group, cells_of_group, find_node_group, &
        nodes_of_group, node_name, find_cell, find_node
    implicit none
    private

    public :: relocate_error, read_groups, group_cells, all_cells, warn_at, read_node_groups, &
        group_first_node, mark_cells, mark_nodes, mark_nodes_of_cells

contains

    !> The group names of keyword `key` (e.g. GROUP_MA), each checked against the cell
    !> groups of `mesh`.
    !>  names : out, the names as written;  groups : out, their group numbers
    !>  st    : out, error located at `key`: no such group (with a did-you-mean)
    subroutine read_groups(kws, key, mesh, names, groups, st)
        class(keyword_set_t), intent(in) :: kws
        character(len=*), intent(in) :: key
        type(mesh_t), intent(in) :: mesh
        type(string_t), allocatable, intent(out) :: names(:)
        integer(i4), allocatable, intent(out) :: groups(:)
        type(status_t), intent(out) :: st
        call read_group_names(kws, key, mesh, .true., names, groups, st)
    end subroutine read_groups

    !> As read_groups, for node groups (GROUP_NO, UNION of CREA_GROUP_NO, ...).
    subroutine read_node_groups(kws, key, mesh, names, groups, st)
        class(keyword_set_t), intent(in) :: kws
        character(len=*), intent(in) :: key
        type(mesh_t), intent(in) :: mesh
        type(string_t), allocatable, intent(out) :: names(:)
        integer(i4), allocatable, intent(out) :: groups(:)
        type(status_t), intent(out) :: st
        call read_group_names(kws, key, mesh, .false., names, groups, st)
    end subroutine read_node_groups

    ! The names of keyword `key` and their numbers among the cell groups (cells) or the node
    ! groups of `mesh`.
    subroutine read_group_names(kws, key, mesh, cells, names, groups, st)
        class(keyword_set_t), intent(in) :: kws
        character(len=*), intent(in) :: key
        type(mesh_t), intent(in) :: mesh
        logical, intent(in) :: cells
        type(string_t), allocatable, intent(out) :: names(:)
        integer(i4), allocatable, intent(out) :: groups(:)
        type(status_t), intent(out) :: st
        integer(i4) :: g
        call kws%get_texts(key, names, st)
        if (st%failed()) return
        allocate (groups(size(names)))
        do g = 1, size(names)
            if (cells) then
                groups(g) = find_cell_group(mesh, names(g)%s, st)
            else
                groups(g) = find_node_group(mesh, names(g)%s, st)
            end if
            if (st%failed()) then
                call relocate_error(kws, key, st)
                return
            end if
        end do
    end subroutine read_group_names

    !> All cells of the groups of keyword `key`, concatenated in the order given.
    !>  st : out, error located at `key` for a group missing in the mesh
    subroutine group_cells(kws, key, mesh, cells, st)
        class(keyword_set_t), intent(in) :: kws
        character(len=*), intent(in) :: key
        type(mesh_t), intent(in) :: mesh
        integer(i4), allocatable, intent(out) :: cells(:)
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        integer(i4), allocatable :: groups(:), members(:)
        integer(i4) :: g, n
        call read_groups(kws, key, mesh, names, groups, st)
        if (st%failed()) return
        n = 0
        do g = 1, size(groups)
            n = n + size(cells_of_group(mesh, groups(g)), kind=i4)
        end do
        allocate (cells(n))
        n = 0
        do g = 1, size(groups)
            members = cells_of_group(mesh, groups(g))
            cells(n + 1:n + size(members)) = members
            n = n + size(members, kind=i4)
        end do
    end subroutine group_cells

    !> Writes a located warning `deck.comm:L:C: warning: COMMAND/FACTOR/KEY: message` (the
    !> .mess and standard error): Code_Aster's alarms, which let the run go on.
    subroutine warn_at(ctx, kws, key, message)
        type(run_context_t), intent(in) :: ctx
        class(keyword_set_t), intent(in) :: kws
        character(len=*), intent(in) :: key, message
        type(status_t) :: located
        character(len=:), allocatable :: text
        integer :: k
        call kws%error_at(key, message, located)
        text = format_status(located)
        k = index(text, 'error: ')
        if (k > 0) text = text(1:k - 1) // 'warning: ' // text(k + 7:)
        call ctx%write_warning(text)
    end subroutine warn_at

    !> The node a one-node group names (GROUP_NO_CENTRE, GROUP_NO_ORIG, ...): its first node,
    !> with a warning when the group holds several (Code_Aster's utnono takes the first).
    !>  st : out, error at `key`: no such group, or an empty group
    subroutine group_first_node(ctx, kws, key, mesh, node, st)
        type(run_context_t), intent(in) :: ctx
        class(keyword_set_t), intent(in) :: kws
        character(len=*), intent(in) :: key
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(out) :: node
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        integer(i4), allocatable :: groups(:), members(:)
        node = 0
        call read_node_groups(kws, key, mesh, names, groups, st)
        if (st%failed()) return
        members = nodes_of_group(mesh, groups(1))
        if (size(members) == 0) then
            call kws%error_at(key, 'GROUP_NO ' // names(1)%s // ' is empty (a node is ' // &
                              'needed)', st)
            return
        end if
        node = members(1)
        if (size(members) > 1) call warn_at(ctx, kws, key, 'GROUP_NO ' // names(1)%s // &
            ' holds ' // to_text(size(members, kind=i4)) // ' nodes: its first, ' // &
            node_name(mesh, node) // ', is taken')
    end subroutine group_first_node

    !> 1, 2, ..., n_cells (TOUT='OUI').
    function all_cells(mesh) result(cells)
        type(mesh_t), intent(in) :: mesh
        integer(i4), allocatable :: cells(:)
        integer(i4) :: c
        allocate (cells(mesh%n_cells))
        do c = 1, mesh%n_cells
            cells(c) = c
        end do
    end function all_cells

    !> Marks in `mask` the cells that keyword `groups` (GROUP_MA, ...) and keyword `names`
    !> (MAILLE, ...) of `occ` name; keywords absent from occ mark nothing.
    !>  mask : inout, one entry per cell, set .true. for the named cells (others untouched)
    !>  st   : out, an unknown group or cell located at its keyword
    subroutine mark_cells(occ, groups, names, mesh, mask, st)
        class(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: groups, names
        type(mesh_t), intent(in) :: mesh
        logical, intent(inout) :: mask(:)
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: words(:)
        integer(i4) :: k, g
        if (occ%has(groups)) then
            call occ%get_texts(groups, words, st)
            if (st%failed()) return
            do k = 1, size(words, kind=i4)
                g = find_cell_group(mesh, words(k)%s, st)
                if (st%failed()) then
                    call relocate_error(occ, groups, st)
                    return
                end if
                mask(cells_of_group(mesh, g)) = .true.
            end do
        end if
        if (occ%has(names)) then
            call occ%get_texts(names, words, st)
            if (st%failed()) return
            do k = 1, size(words, kind=i4)
                g = find_cell(mesh, words(k)%s, st)
                if (st%failed()) then
                    call relocate_error(occ, names, st)
                    return
                end if
                mask(g) = .true.
            end do
        end if
    end subroutine mark_cells

    !> As mark_cells, for nodes: keyword `groups` (GROUP_NO, ...) and `names` (NOEUD, ...).
    subroutine mark_nodes(occ, groups, names, mesh, mask, st)
        class(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: groups, names
        type(mesh_t), intent(in) :: mesh
        logical, intent(inout) :: mask(:)
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: words(:)
        integer(i4) :: k, g
        if (occ%has(groups)) then
            call occ%get_texts(groups, words, st)
            if (st%failed()) return
            do k = 1, size(words, kind=i4)
                g = find_node_group(mesh, words(k)%s, st)
                if (st%failed()) then
                    call relocate_error(occ, groups, st)
                    return
                end if
                mask(nodes_of_group(mesh, g)) = .true.
            end do
        end if
        if (occ%has(names)) then
            call occ%get_texts(names, words, st)
            if (st%failed()) return
            do k = 1, size(words, kind=i4)
                g = find_node(mesh, words(k)%s, st)
                if (st%failed()) then
                    call relocate_error(occ, names, st)
                    return
                end if
                mask(g) = .true.
            end do
        end if
    end subroutine mark_nodes

    !> Marks in `node_mask` the nodes of the cells of `cell_mask`.
    pure subroutine mark_nodes_of_cells(mesh, cell_mask, node_mask)
        type(mesh_t), intent(in) :: mesh
        logical, intent(in) :: cell_mask(:)
        logical, intent(inout) :: node_mask(:)
        integer(i4) :: c
        do c = 1, mesh%n_cells
            if (cell_mask(c)) node_mask(mesh%cell_nodes(mesh%cell_ptr(c):mesh%cell_ptr(c + 1) &
                - 1)) = .true.
        end do
    end subroutine mark_nodes_of_cells

end module mesh_command_support

