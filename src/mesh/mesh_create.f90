!> The new meshes of CREA_MAILLAGE (U4.23.02), built from an existing one as Code_Aster
!> builds them (op0167, cmqutr, crea_maillage_module, cmmoma):
!>  - add_point_cells (CREA_POI1): a POI1 on every node chosen by the occurrences (one per
!>    node, in increasing node number), after the cells; each occurrence's NOM_GROUP_MA holds
!>    the POI1 of its nodes;
!>  - duplicate_cells (CREA_MAILLE): copies of the chosen cells after the cells, a group per
!>    occurrence;
!>  - split_quadrangles (MODI_MAILLE QUAD_TRIA3): every chosen QUAD4 into TRIA3 (1 2 3),
!>    (1 3 4), QUAD8 and QUAD9 into six TRIA3 on their corner and mid-edge nodes, the
!>    triangles taking the quadrangle's place in the numbering; a group holding a quadrangle
!>    holds its triangles, members in cell order;
!>  - add_face_centres (MODI_MAILLE QUAD8_9): a centre node on every chosen QUAD8 (at the
!>    centre of the serendipity map, -1/4 of the corners + 1/2 of the mid-edge nodes), numbered
!>    after the nodes in the order of the cells;
!>  - to_quadratic (LINE_QUAD): SEG2, TRIA3, QUAD4 into SEG3, TRIA6, QUAD8, a node in the
!>    middle of every edge, shared by the cells of the edge (with the mid node of a quadratic
!>    cell already on it), new nodes numbered after the nodes in the order the cells are met
!>    (increasing number, each cell's edges in turn); node groups keep their nodes;
!>  - to_linear (QUAD_LINE): SEG3, TRIA6, QUAD8, QUAD9 into SEG2, TRIA3, QUAD4; the nodes no
!>    cell uses any more are removed (a node of no cell before stays), the others numbered
!>    again in their order; node groups lose the removed nodes (an emptied group goes).
!> Names: entities that keep their number keep their name; new ones, and all of a family
!> that is numbered again, are named N<number> / M<number> (Code_Aster's meshes name them by
!> number), with a suffix when such a name is taken. Every operation is O(n) (edges found
!> through the node-to-edge lists of edge_table_t).
module mesh_create
    use kinds, only: dp, i4, i8
    use status, only: status_t, clear_status
    use mesh_types, only: mesh_t, mesh_add_node, mesh_add_cell, mesh_add_node_group, &
        mesh_add_cell_group, mesh_finish, node_group_name, cell_group_name, n_node_groups, &
        n_cell_groups, nodes_of_group, cells_of_group, mesh_remove_node_groups, &
        mesh_remove_cell_groups
    use mesh_name_index, only: name_index_t, name_find, name_add, numbered_name
    use mesh_cell_shapes, only: CELL_POI1, CELL_SEG2, CELL_SEG3, CELL_TRIA3, CELL_TRIA6, &
        CELL_QUAD4, CELL_QUAD8, CELL_QUAD9, CELL_TYPE_CORNERS, CELL_TYPE_NODES, &
        CELL_TYPE_LINEAR, cell_type_is_quadratic
    implicit none
    private

    public :: add_point_cells, duplicate_cells, split_quadrangles, add_face_centres, &
        to_quadratic, to_linear

    !> Edges -> mid nodes: for each node, the edges whose smaller end it is (their other
    !> end and mid node), in compressed rows sized by a first count of the cells' edges.
    !> Looking an edge up scans a handful of entries stored near those of neighbouring nodes,
    !> so a structured mesh is walked through memory in order (a hash table's random probes
    !> cost a cache miss each).
    type :: edge_table_t
        integer(i4), allocatable :: ptr(:), fill(:), other(:), mid(:)
    end type edge_table_t

contains

    !> CREA_POI1. nodes(:, occurrence) flags in `chosen` (n_nodes, n_occurrences); `names`
    !> the NOM_GROUP_MA of each occurrence ('' for none).
    subroutine add_point_cells(mesh, chosen, names, out, st)
        type(mesh_t), intent(in) :: mesh
        logical, intent(in) :: chosen(:, :)
        character(len=*), intent(in) :: names(:)
        type(mesh_t), intent(out) :: out
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: point_cell(:), members(:)
        integer(i4) :: n, c, o
        out = mesh
        allocate (point_cell(mesh%n_nodes), source=0_i4)
        c = mesh%n_cells
        do n = 1, mesh%n_nodes
            if (.not. any(chosen(n, :))) cycle
            c = c + 1
            call mesh_add_cell(out, fresh_name(out%cell_names, 'M', c), CELL_POI1, [n], 0, st)
            if (st%failed()) return
            point_cell(n) = c
        end do
        do o = 1, size(names)
            if (len_trim(names(o)) == 0) cycle
            members = pack(point_cell, chosen(:, o))
            call mesh_add_cell_group(out, trim(names(o)), members, 0, st)
            if (st%failed()) return
        end do
        call mesh_finish(out, 0, st, check_cells=.false.)
    end subroutine add_point_cells

    !> CREA_MAILLE: copies of the cells of each occurrence (`cells(ptr(o):ptr(o+1)-1)`) after
    !> the cells, in group `names(o)`.
    subroutine duplicate_cells(mesh, cells, ptr, names, out, st)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:), ptr(:)
        character(len=*), intent(in) :: names(:)
        type(mesh_t), intent(out) :: out
        type(status_t), intent(out) :: st
        integer(i4) :: o, i, c
        integer(i4), allocatable :: members(:)
        out = mesh
        c = mesh%n_cells
        do i = 1, size(cells, kind=i4)
            c = c + 1
            call mesh_add_cell(out, fresh_name(out%cell_names, 'M', c), &
                mesh%cell_type(cells(i)), &
                mesh%cell_nodes(mesh%cell_ptr(cells(i)):mesh%cell_ptr(cells(i) + 1) - 1), &
                mesh%cell_line(cells(i)), st)
            if (st%failed()) return
        end do
        c = mesh%n_cells
        do o = 1, size(names)
            members = [(c + i, i = ptr(o), ptr(o + 1) - 1)]
            call mesh_add_cell_group(out, trim(names(o)), members, 0, st)
            if (st%failed()) return
        end do
        call mesh_finish(out, 0, st, check_cells=.false.)
    end subroutine duplicate_cells

    !> QUAD_TRIA3 on the cells flagged in `chosen` (other types left as they are).
    !>  split : out, the number of quadrangles split
    subroutine split_quadrangles(mesh, chosen, out, split, st)
        type(mesh_t), intent(in) :: mesh
        logical, intent(in) :: chosen(:)
        type(mesh_t), intent(out) :: out
        integer(i4), intent(out) :: split
        type(status_t), intent(out) :: st
        ! cmqutr / irgmtb: the triangles of a QUAD4, and of a QUAD8 or QUAD9
        integer(i4), parameter :: Q4(3, 2) = reshape([1, 2, 3, 1, 3, 4], [3, 2])
        integer(i4), parameter :: Q8(3, 6) = reshape([1, 5, 8, 5, 2, 6, 6, 3, 7, 7, 4, 8, &
                                                      5, 7, 8, 5, 6, 7], [3, 6])
        integer(i4), allocatable :: first(:), pieces(:), members(:), types(:), ptr(:), &
            nodes(:), lines(:)
        logical, allocatable :: every(:)
        integer(i4) :: c, k, m, g, i, t, p0, q, total
        type(name_index_t) :: names
        allocate (first(mesh%n_cells + 1), pieces(mesh%n_cells))
        split = 0
        do c = 1, mesh%n_cells
            t = mesh%cell_type(c)
            pieces(c) = 1
            if (chosen(c) .and. t == CELL_QUAD4) pieces(c) = 2
            if (chosen(c) .and. (t == CELL_QUAD8 .or. t == CELL_QUAD9)) pieces(c) = 6
            if (pieces(c) > 1) split = split + 1
        end do
        first(1) = 1
        do c = 1, mesh%n_cells
            first(c + 1) = first(c) + pieces(c)
        end do
        total = first(mesh%n_cells + 1) - 1
        allocate (types(total), ptr(total + 1), lines(total))
        allocate (nodes(size(mesh%cell_nodes) + 3 * 6 * split))
        ptr(1) = 1
        m = 0
        do c = 1, mesh%n_cells
            p0 = mesh%cell_ptr(c) - 1
            do k = 1, pieces(c)
                m = m + 1
                lines(m) = mesh%cell_line(c)
                q = ptr(m)
                if (pieces(c) == 1) then
                    types(m) = mesh%cell_type(c)
                    i = mesh%cell_ptr(c + 1) - mesh%cell_ptr(c)
                    nodes(q:q + i - 1) = mesh%cell_nodes(p0 + 1:p0 + i)
                else
                    types(m) = CELL_TRIA3
                    i = 3
                    if (pieces(c) == 2) then
                        nodes(q:q + 2) = mesh%cell_nodes(p0 + Q4(:, k))
                    else
                        nodes(q:q + 2) = mesh%cell_nodes(p0 + Q8(:, k))
                    end if
                end if
                ptr(m + 1) = q + i
            end do
        end do
        do m = 1, total
            call name_add(names, numbered_name('M', m), i)
        end do
        out = mesh
        out%n_cells = total
        call move_alloc(types, out%cell_type)
        call move_alloc(ptr, out%cell_ptr)
        call move_alloc(lines, out%cell_line)
        out%cell_nodes = nodes(1:out%cell_ptr(total + 1) - 1)
        out%cell_names = names
        ! a group holding a quadrangle holds its pieces, members in cell order
        allocate (every(n_cell_groups(mesh)), source=.true.)
        call mesh_remove_cell_groups(out, every)
        do g = 1, n_cell_groups(mesh)
            members = sort_unique(cells_of_group(mesh, g), mesh%n_cells)
            members = [((first(members(i)) + k - 1, k = 1, pieces(members(i))), &
                        i = 1, size(members))]
            call mesh_add_cell_group(out, cell_group_name(mesh, g), members, &
                                     mesh%cell_group_line(g), st)
            if (st%failed()) return
        end do
        call mesh_finish(out, 0, st)
    end subroutine split_quadrangles

    !> QUAD8_9 on the QUAD8 of `cells` (in that order).
    !>  added : out, the QUAD8 turned into QUAD9
    subroutine add_face_centres(mesh, cells, out, added, st)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:)
        type(mesh_t), intent(out) :: out
        integer(i4), intent(out) :: added
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: extra(:, :)
        integer(i4), allocatable :: new_type(:)
        integer(i4) :: i, c, n, p0
        real(dp) :: x(3)
        out = mesh
        allocate (extra(4, mesh%n_cells), source=0_i4)
        new_type = mesh%cell_type
        n = mesh%n_nodes
        added = 0
        do i = 1, size(cells, kind=i4)
            c = cells(i)
            if (mesh%cell_type(c) /= CELL_QUAD8 .or. extra(1, c) > 0) cycle
            p0 = mesh%cell_ptr(c) - 1
            x = 0.5_dp * sum(mesh%coords(:, mesh%cell_nodes(p0 + 5:p0 + 8)), dim=2) &
                - 0.25_dp * sum(mesh%coords(:, mesh%cell_nodes(p0 + 1:p0 + 4)), dim=2)
            n = n + 1
            call add_named_node(out, n, x, st)
            if (st%failed()) return
            extra(1, c) = n
            new_type(c) = CELL_QUAD9
            added = added + 1
        end do
        call set_connectivity(mesh, out, new_type, extra)
        call mesh_finish(out, 0, st, check_cells=.false.)
    end subroutine add_face_centres

    !> LINE_QUAD on the cells flagged in `chosen`.
    !>  converted : out, the cells made quadratic
    subroutine to_quadratic(mesh, chosen, out, converted, st)
        type(mesh_t), intent(in) :: mesh
        logical, intent(in) :: chosen(:)
        type(mesh_t), intent(out) :: out
        integer(i4), intent(out) :: converted
        type(status_t), intent(out) :: st
        type(edge_table_t) :: edges
        integer(i4), allocatable :: mids(:, :), new_type(:)
        integer(i4) :: c, k, nv, ne, n, a, b, t, mid, p0
        call edge_table_init(edges, mesh, chosen)
        ! the mid nodes quadratic cells already have on their edges
        do c = 1, mesh%n_cells
            t = mesh%cell_type(c)
            if (.not. cell_type_is_quadratic(t)) cycle
            p0 = mesh%cell_ptr(c) - 1
            nv = CELL_TYPE_CORNERS(t)
            do k = 1, merge(1, nv, nv == 2)
                call edge_table_put(edges, mesh%cell_nodes(p0 + k), &
                    mesh%cell_nodes(p0 + mod(k, nv) + 1), mesh%cell_nodes(p0 + nv + k))
            end do
        end do
        ! new mid nodes, in the order of the cells and of their edges
        out = mesh
        allocate (mids(4, mesh%n_cells), source=0_i4)
        new_type = mesh%cell_type
        n = mesh%n_nodes
        converted = 0
        do c = 1, mesh%n_cells
            t = mesh%cell_type(c)
            if (.not. chosen(c) .or. .not. (t == CELL_SEG2 .or. t == CELL_TRIA3 .or. &
                                             t == CELL_QUAD4)) cycle
            converted = converted + 1
            p0 = mesh%cell_ptr(c) - 1
            nv = CELL_TYPE_CORNERS(t)
            ne = merge(1, nv, nv == 2)
            do k = 1, ne
                a = mesh%cell_nodes(p0 + k)
                b = mesh%cell_nodes(p0 + mod(k, nv) + 1)
                mid = edge_table_get(edges, a, b)
                if (mid == 0) then
                    n = n + 1
                    mid = n
                    call add_named_node(out, n, 0.5_dp * (mesh%coords(:, a) + &
                                                          mesh%coords(:, b)), st)
                    if (st%failed()) return
                    call edge_table_put(edges, a, b, mid)
                end if
                mids(k, c) = mid
            end do
            select case (t)
            case (CELL_SEG2)
                new_type(c) = CELL_SEG3
            case (CELL_TRIA3)
                new_type(c) = CELL_TRIA6
            case default
                new_type(c) = CELL_QUAD8
            end select
        end do
        call set_connectivity(mesh, out, new_type, mids)
        call mesh_finish(out, 0, st, check_cells=.false.)
    end subroutine to_quadratic

    !> QUAD_LINE on the cells flagged in `chosen`.
    !>  converted : out, the cells made linear;  removed : out, the nodes removed
    subroutine to_linear(mesh, chosen, out, converted, removed, st)
        type(mesh_t), intent(in) :: mesh
        logical, intent(in) :: chosen(:)
        type(mesh_t), intent(out) :: out
        integer(i4), intent(out) :: converted, removed
        type(status_t), intent(out) :: st
        logical, allocatable :: in_cell(:), used(:), every(:)
        integer(i4), allocatable :: new_number(:), new_type(:), ptr(:), nodes(:), members(:)
        integer(i4) :: c, n, k, g, t, p0, nn, i
        type(name_index_t) :: names
        allocate (in_cell(mesh%n_nodes), used(mesh%n_nodes), source=.false.)
        new_type = mesh%cell_type
        converted = 0
        do c = 1, mesh%n_cells
            t = mesh%cell_type(c)
            p0 = mesh%cell_ptr(c) - 1
            nn = mesh%cell_ptr(c + 1) - mesh%cell_ptr(c)
            in_cell(mesh%cell_nodes(p0 + 1:p0 + nn)) = .true.
            if (chosen(c) .and. cell_type_is_quadratic(t)) then
                new_type(c) = CELL_TYPE_LINEAR(t)
                converted = converted + 1
            end if
            used(mesh%cell_nodes(p0 + 1:p0 + CELL_TYPE_NODES(new_type(c)))) = .true.
        end do
        ! kept: the nodes of the cells as they will be, and those of no cell before
        used = used .or. .not. in_cell
        allocate (new_number(mesh%n_nodes), source=0_i4)
        k = 0
        do n = 1, mesh%n_nodes
            if (.not. used(n)) cycle
            k = k + 1
            new_number(n) = k
        end do
        removed = mesh%n_nodes - k
        out = mesh
        if (removed > 0) then
            out%coords = mesh%coords(:, pack([(n, n = 1, mesh%n_nodes)], used))
            out%n_nodes = k
            do n = 1, k
                call name_add(names, numbered_name('N', n), i)
            end do
            out%node_names = names
        end if
        allocate (ptr(mesh%n_cells + 1), nodes(size(mesh%cell_nodes)))
        ptr(1) = 1
        do c = 1, mesh%n_cells
            p0 = mesh%cell_ptr(c) - 1
            nn = CELL_TYPE_NODES(new_type(c))
            nodes(ptr(c):ptr(c) + nn - 1) = new_number(mesh%cell_nodes(p0 + 1:p0 + nn))
            ptr(c + 1) = ptr(c) + nn
        end do
        call move_alloc(new_type, out%cell_type)
        call move_alloc(ptr, out%cell_ptr)
        out%cell_nodes = nodes(1:out%cell_ptr(mesh%n_cells + 1) - 1)
        if (removed > 0) then
            allocate (every(n_node_groups(mesh)), source=.true.)
            call mesh_remove_node_groups(out, every)
            do g = 1, n_node_groups(mesh)
                members = nodes_of_group(mesh, g)
                members = new_number(pack(members, used(members)))
                if (size(members) == 0) cycle
                call mesh_add_node_group(out, node_group_name(mesh, g), members, &
                                         mesh%node_group_line(g), st)
                if (st%failed()) return
            end do
        end if
        call mesh_finish(out, 0, st, check_cells=.false.)
    end subroutine to_linear

    ! The connectivity of `out` made from `mesh`'s with each cell's type new_type(c) and its
    ! nodes followed by the nonzero ones of extra(:, c) (mid-edge or centre nodes added).
    subroutine set_connectivity(mesh, out, new_type, extra)
        type(mesh_t), intent(in) :: mesh
        type(mesh_t), intent(inout) :: out
        integer(i4), allocatable, intent(inout) :: new_type(:)
        integer(i4), intent(in) :: extra(:, :)
        integer(i4), allocatable :: ptr(:), nodes(:)
        integer(i4) :: c, p0, nn, ne
        allocate (ptr(mesh%n_cells + 1), nodes(size(mesh%cell_nodes) + count(extra > 0)))
        ptr(1) = 1
        do c = 1, mesh%n_cells
            p0 = mesh%cell_ptr(c) - 1
            nn = mesh%cell_ptr(c + 1) - mesh%cell_ptr(c)
            ne = count(extra(:, c) > 0, kind=i4)
            nodes(ptr(c):ptr(c) + nn - 1) = mesh%cell_nodes(p0 + 1:p0 + nn)
            nodes(ptr(c) + nn:ptr(c) + nn + ne - 1) = extra(1:ne, c)
            ptr(c + 1) = ptr(c) + nn + ne
        end do
        call move_alloc(new_type, out%cell_type)
        call move_alloc(ptr, out%cell_ptr)
        call move_alloc(nodes, out%cell_nodes)
    end subroutine set_connectivity

    ! ---- helpers -------------------------------------------------------------------------

    ! Node number n (the next one) named N<n>, or N<n>_<k> when that name is taken (the add
    ! fails only for a taken name: the coordinates come from the mesh's own).
    subroutine add_named_node(out, n, x, st)
        type(mesh_t), intent(inout) :: out
        integer(i4), intent(in) :: n
        real(dp), intent(in) :: x(3)
        type(status_t), intent(out) :: st
        call mesh_add_node(out, numbered_name('N', n), x, 0, st)
        if (st%ok()) return
        call clear_status(st)
        call mesh_add_node(out, fresh_name(out%node_names, 'N', n), x, 0, st)
    end subroutine add_named_node

    ! prefix<number>, or prefix<number>_<k> with the smallest k that makes it new.
    function fresh_name(names, prefix, number) result(name)
        type(name_index_t), intent(in) :: names
        character(len=*), intent(in) :: prefix
        integer(i4), intent(in) :: number
        character(len=:), allocatable :: name
        integer(i4) :: k
        name = numbered_name(prefix, number)
        k = 0
        do while (name_find(names, name) > 0)
            k = k + 1
            name = numbered_name(prefix, number) // numbered_name('_', k)
        end do
    end function fresh_name

    ! The distinct values of a (1..n) in increasing order.
    function sort_unique(a, n) result(b)
        integer(i4), intent(in) :: a(:), n
        integer(i4), allocatable :: b(:)
        logical, allocatable :: seen(:)
        integer(i4) :: i
        allocate (seen(n), source=.false.)
        seen(a) = .true.
        b = pack([(i, i = 1, n)], seen)
    end function sort_unique

    ! Room for the edges of the cells flagged in `take` (and those of every quadratic
    ! cell).
    subroutine edge_table_init(table, mesh, take)
        type(edge_table_t), intent(out) :: table
        type(mesh_t), intent(in) :: mesh
        logical, intent(in) :: take(:)
        integer(i4) :: c, k, nv, p0, n, t
        allocate (table%ptr(mesh%n_nodes + 1), source=0_i4)
        do c = 1, mesh%n_cells
            t = mesh%cell_type(c)
            if (.not. (take(c) .or. cell_type_is_quadratic(t))) cycle
            if (CELL_TYPE_CORNERS(t) < 2) cycle
            p0 = mesh%cell_ptr(c) - 1
            nv = CELL_TYPE_CORNERS(t)
            do k = 1, merge(1, nv, nv == 2)
                n = min(mesh%cell_nodes(p0 + k), mesh%cell_nodes(p0 + mod(k, nv) + 1))
                table%ptr(n + 1) = table%ptr(n + 1) + 1
            end do
        end do
        table%ptr(1) = 1
        do n = 1, mesh%n_nodes
            table%ptr(n + 1) = table%ptr(n + 1) + table%ptr(n)
        end do
        allocate (table%fill(mesh%n_nodes), source=0_i4)
        allocate (table%other(table%ptr(mesh%n_nodes + 1) - 1), &
                  table%mid(table%ptr(mesh%n_nodes + 1) - 1))
    end subroutine edge_table_init

    ! The mid node of edge (a, b) (either order), 0 if it has none yet.
    integer(i4) function edge_table_get(table, a, b) result(mid)
        type(edge_table_t), intent(in) :: table
        integer(i4), intent(in) :: a, b
        integer(i4) :: lo, hi, k
        lo = min(a, b)
        hi = max(a, b)
        mid = 0
        do k = table%ptr(lo), table%ptr(lo) + table%fill(lo) - 1
            if (table%other(k) == hi) then
                mid = table%mid(k)
                return
            end if
        end do
    end function edge_table_get

    ! Records the mid node of edge (a, b) (a first one stays).
    subroutine edge_table_put(table, a, b, mid)
        type(edge_table_t), intent(inout) :: table
        integer(i4), intent(in) :: a, b, mid
        integer(i4) :: lo, k
        if (edge_table_get(table, a, b) > 0) return
        lo = min(a, b)
        k = table%ptr(lo) + table%fill(lo)
        table%other(k) = max(a, b)
        table%mid(k) = mid
        table%fill(lo) = table%fill(lo) + 1
    end subroutine edge_table_put

end module mesh_create
