!> CREA_MAILLAGE RESTREINT (U4.23.02): a mesh reduced to some of its cells, as Code_Aster
!> reduces one (rdtmai):
!>  - cells: the chosen ones, in increasing number;
!>  - nodes: those of the kept cells, numbered in the order the kept cells meet them, then
!>    the extra nodes asked for (RESTREINT's GROUP_NO) that no kept cell has, in increasing
!>    number; coordinates as they are;
!>  - groups: the cell groups and node groups asked for, each reduced to its kept members in
!>    its own order; a group left empty is not made;
!>  - names: Code_Aster's meshes name entities by number: a family numbered again is named
!>    N<number> / M<number>; a family kept whole in its order keeps its names.
!> O(n) in the size of the mesh (one pass over the cells, one over each group; the arrays
!> are made whole, not cell by cell through mesh_add_cell: doc/performance.md).
module mesh_restrict
    use kinds, only: i4
    use status, only: status_t
    use mesh_types, only: mesh_t, mesh_add_node_group, mesh_add_cell_group, mesh_finish, &
        nodes_of_group, cells_of_group, node_group_name, cell_group_name, n_node_groups, &
        n_cell_groups, mesh_remove_node_groups, mesh_remove_cell_groups
    use mesh_name_index, only: name_index_t, name_add, numbered_name
    implicit none
    private

    public :: restrict_mesh

contains

    !> The mesh of `cells` (increasing cell numbers, each once) and `extra_nodes` (increasing
    !> node numbers), with the cell groups `cell_groups` and node groups `node_groups` (group
    !> numbers of `mesh`) reduced to what is kept (module header).
    !>  made_ma, made_no : out, the cell and node groups made (the others were left empty)
    subroutine restrict_mesh(mesh, cells, extra_nodes, cell_groups, node_groups, out, &
                             made_ma, made_no, st)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:), extra_nodes(:), cell_groups(:), node_groups(:)
        type(mesh_t), intent(out) :: out
        integer(i4), intent(out) :: made_ma, made_no
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: new_node(:), new_cell(:), old_node(:), members(:)
        integer(i4) :: i, k, c, n, n_kept, g
        logical :: same_nodes, same_cells
        logical, allocatable :: no_group(:)
        made_ma = 0
        made_no = 0
        allocate (new_node(mesh%n_nodes), source=0_i4)
        allocate (old_node(mesh%n_nodes))
        n_kept = 0
        do i = 1, size(cells, kind=i4)
            c = cells(i)
            do k = mesh%cell_ptr(c), mesh%cell_ptr(c + 1) - 1
                n = mesh%cell_nodes(k)
                if (new_node(n) > 0) cycle
                n_kept = n_kept + 1
                new_node(n) = n_kept
                old_node(n_kept) = n
            end do
        end do
        do i = 1, size(extra_nodes, kind=i4)
            n = extra_nodes(i)
            if (new_node(n) > 0) cycle
            n_kept = n_kept + 1
            new_node(n) = n_kept
            old_node(n_kept) = n
        end do
        same_nodes = n_kept == mesh%n_nodes
        if (same_nodes) same_nodes = all(old_node(1:n_kept) == [(n, n = 1, n_kept)])
        same_cells = size(cells) == mesh%n_cells   ! increasing and each once: all, in order
        allocate (new_cell(mesh%n_cells), source=0_i4)
        new_cell(cells) = [(i, i = 1, size(cells, kind=i4))]
        ! the new mesh starts as a copy (names kept when a family is), without its groups
        out = mesh
        allocate (no_group(n_cell_groups(mesh)), source=.true.)
        call mesh_remove_cell_groups(out, no_group)
        deallocate (no_group)
        allocate (no_group(n_node_groups(mesh)), source=.true.)
        call mesh_remove_node_groups(out, no_group)
        out%n_nodes = n_kept
        out%coords = mesh%coords(:, old_node(1:n_kept))
        if (.not. same_nodes) out%node_names = numbered_names('N', n_kept)
        out%n_cells = size(cells, kind=i4)
        out%cell_type = mesh%cell_type(cells)
        out%cell_line = mesh%cell_line(cells)
        deallocate (out%cell_ptr, out%cell_nodes)
        allocate (out%cell_ptr(out%n_cells + 1))
        out%cell_ptr(1) = 1
        do i = 1, out%n_cells
            c = cells(i)
            out%cell_ptr(i + 1) = out%cell_ptr(i) + mesh%cell_ptr(c + 1) - mesh%cell_ptr(c)
        end do
        allocate (out%cell_nodes(out%cell_ptr(out%n_cells + 1) - 1))
        do i = 1, out%n_cells
            c = cells(i)
            out%cell_nodes(out%cell_ptr(i):out%cell_ptr(i + 1) - 1) = &
                new_node(mesh%cell_nodes(mesh%cell_ptr(c):mesh%cell_ptr(c + 1) - 1))
        end do
        if (.not. same_cells) out%cell_names = numbered_names('M', out%n_cells)
        do i = 1, size(cell_groups, kind=i4)
            g = cell_groups(i)
            members = cells_of_group(mesh, g)
            members = new_cell(pack(members, new_cell(members) > 0))
            if (size(members) == 0) cycle
            call mesh_add_cell_group(out, cell_group_name(mesh, g), members, &
                                     mesh%cell_group_line(g), st)
            if (st%failed()) return
            made_ma = made_ma + 1
        end do
        do i = 1, size(node_groups, kind=i4)
            g = node_groups(i)
            members = nodes_of_group(mesh, g)
            members = new_node(pack(members, new_node(members) > 0))
            if (size(members) == 0) cycle
            call mesh_add_node_group(out, node_group_name(mesh, g), members, &
                                     mesh%node_group_line(g), st)
            if (st%failed()) return
            made_no = made_no + 1
        end do
        call mesh_finish(out, 0, st, check_cells=.false.)
    end subroutine restrict_mesh

    ! prefix1 .. prefix<n>, Code_Aster's names by number.
    function numbered_names(prefix, n) result(names)
        character(len=*), intent(in) :: prefix
        integer(i4), intent(in) :: n
        type(name_index_t) :: names
        integer(i4) :: i, index
        do i = 1, n
            call name_add(names, numbered_name(prefix, i), index)
        end do
    end function numbered_names

end module mesh_restrict
