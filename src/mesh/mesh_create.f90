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
!> in a hash table).
module mesh_create
    use kinds, only: dp, i4, i8
    use status, only: status_t
    use strings, only: to_text
    use mesh_types, only: mesh_t, mesh_init, mesh_add_node, mesh_add_cell, &
        mesh_add_node_group, mesh_add_cell_group, mesh_finish, node_name, cell_name, &
        node_group_name, cell_group_name, n_node_groups, n_cell_groups, nodes_of_group, &
        cells_of_group
    use mesh_name_index, only: name_index_t, name_find
    use mesh_cell_shapes, only: CELL_POI1, CELL_SEG2, CELL_SEG3, CELL_TRIA3, CELL_TRIA6, &
        CELL_QUAD4, CELL_QUAD8, CELL_QUAD9, CELL_TYPE_CORNERS, CELL_TYPE_NODES, &
        CELL_TYPE_LINEAR, cell_type_is_quadratic
    implicit none
    private

    public :: add_point_cells, duplicate_cells, split_quadrangles, add_face_centres, &
        to_quadratic, to_linear

    !> Edges -> mid nodes (open addressing on the key min*(n+1)+max of their end nodes).
    type :: edge_table_t
        integer(i8), allocatable :: keys(:)
        integer(i4), allocatable :: mids(:)
        integer(i8) :: stride = 0
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
        call copy_nodes(mesh, out, st)
        if (st%ok()) call copy_cells(mesh, out, st)
        if (st%failed()) return
        allocate (point_cell(mesh%n_nodes), source=0_i4)
        c = mesh%n_cells
        do n = 1, mesh%n_nodes
            if (.not. any(chosen(n, :))) cycle
            c = c + 1
            call mesh_add_cell(out, fresh_name(out%cell_names, 'M', c), CELL_POI1, [n], 0, st)
            if (st%failed()) return
            point_cell(n) = c
        end do
        call copy_groups(mesh, out, st)
        if (st%failed()) return
        do o = 1, size(names)
            if (len_trim(names(o)) == 0) cycle
            members = pack(point_cell, chosen(:, o))
            call mesh_add_cell_group(out, trim(names(o)), members, 0, st)
            if (st%failed()) return
        end do
        call mesh_finish(out, 0, st)
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
        call copy_nodes(mesh, out, st)
        if (st%ok()) call copy_cells(mesh, out, st)
        if (st%failed()) return
        c = mesh%n_cells
        do i = 1, size(cells, kind=i4)
            c = c + 1
            call mesh_add_cell(out, fresh_name(out%cell_names, 'M', c), &
                mesh%cell_type(cells(i)), cell_nodes(mesh, cells(i)), &
                mesh%cell_line(cells(i)), st)
            if (st%failed()) return
        end do
        call copy_groups(mesh, out, st)
        if (st%failed()) return
        c = mesh%n_cells
        do o = 1, size(names)
            members = [(c + i, i = ptr(o), ptr(o + 1) - 1)]
            call mesh_add_cell_group(out, trim(names(o)), members, 0, st)
            if (st%failed()) return
        end do
        call mesh_finish(out, 0, st)
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
        integer(i4), allocatable :: first(:), count(:), nodes(:), members(:), pieces(:, :)
        integer(i4) :: c, k, m, g, i, t
        call copy_nodes(mesh, out, st)
        if (st%failed()) return
        allocate (first(mesh%n_cells), count(mesh%n_cells))
        m = 0
        split = 0
        do c = 1, mesh%n_cells
            nodes = cell_nodes(mesh, c)
            t = mesh%cell_type(c)
            first(c) = m + 1
            if (chosen(c) .and. (t == CELL_QUAD4 .or. t == CELL_QUAD8 .or. t == CELL_QUAD9)) then
                split = split + 1
                if (t == CELL_QUAD4) then
                    pieces = Q4
                else
                    pieces = Q8
                end if
                count(c) = size(pieces, 2, kind=i4)
                do k = 1, count(c)
                    m = m + 1
                    call mesh_add_cell(out, 'M' // to_text(m), CELL_TRIA3, nodes(pieces(:, k)), &
                                       mesh%cell_line(c), st)
                    if (st%failed()) return
                end do
            else
                count(c) = 1
                m = m + 1
                call mesh_add_cell(out, 'M' // to_text(m), t, nodes, mesh%cell_line(c), st)
                if (st%failed()) return
            end if
        end do
        call copy_node_groups(mesh, out, st)
        if (st%failed()) return
        do g = 1, n_cell_groups(mesh)
            ! members in cell order, each cell by its pieces
            members = sort_unique(cells_of_group(mesh, g), mesh%n_cells)
            members = [((first(members(i)) + k - 1, k = 1, count(members(i))), &
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
        integer(i4), allocatable :: centre(:), nodes(:)
        integer(i4) :: i, c, n
        real(dp) :: x(3)
        call copy_nodes(mesh, out, st)
        if (st%failed()) return
        allocate (centre(mesh%n_cells), source=0_i4)
        n = mesh%n_nodes
        added = 0
        do i = 1, size(cells, kind=i4)
            c = cells(i)
            if (mesh%cell_type(c) /= CELL_QUAD8 .or. centre(c) > 0) cycle
            nodes = cell_nodes(mesh, c)
            x = 0.5_dp * sum(mesh%coords(:, nodes(5:8)), dim=2) &
                - 0.25_dp * sum(mesh%coords(:, nodes(1:4)), dim=2)
            n = n + 1
            call mesh_add_node(out, fresh_name(out%node_names, 'N', n), x, 0, st)
            if (st%failed()) return
            centre(c) = n
            added = added + 1
        end do
        do c = 1, mesh%n_cells
            if (centre(c) > 0) then
                call mesh_add_cell(out, cell_name(mesh, c), CELL_QUAD9, &
                    [cell_nodes(mesh, c), centre(c)], mesh%cell_line(c), st)
            else
                call mesh_add_cell(out, cell_name(mesh, c), mesh%cell_type(c), &
                    cell_nodes(mesh, c), mesh%cell_line(c), st)
            end if
            if (st%failed()) return
        end do
        call copy_groups(mesh, out, st)
        if (st%ok()) call mesh_finish(out, 0, st)
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
        integer(i4), allocatable :: nodes(:), mids(:, :)
        integer(i4) :: c, k, nv, n, a, b, t, mid
        real(dp), allocatable :: new_coords(:, :)
        call edge_table_init(edges, mesh%n_nodes, 4 * mesh%n_cells + 8)
        ! the mid nodes quadratic cells already have on their edges
        do c = 1, mesh%n_cells
            t = mesh%cell_type(c)
            if (.not. cell_type_is_quadratic(t)) cycle
            nodes = cell_nodes(mesh, c)
            nv = CELL_TYPE_CORNERS(t)
            do k = 1, merge(1, nv, nv == 2)
                call edge_table_put(edges, nodes(k), nodes(mod(k, nv) + 1), nodes(nv + k))
            end do
        end do
        ! new mid nodes, in the order of the cells and of their edges
        allocate (mids(4, mesh%n_cells), source=0_i4)
        allocate (new_coords(3, 4 * count(chosen)))
        n = mesh%n_nodes
        converted = 0
        do c = 1, mesh%n_cells
            t = mesh%cell_type(c)
            if (.not. chosen(c) .or. .not. (t == CELL_SEG2 .or. t == CELL_TRIA3 .or. &
                                             t == CELL_QUAD4)) cycle
            converted = converted + 1
            nodes = cell_nodes(mesh, c)
            nv = CELL_TYPE_CORNERS(t)
            do k = 1, merge(1, nv, nv == 2)
                a = nodes(k)
                b = nodes(mod(k, nv) + 1)
                mid = edge_table_get(edges, a, b)
                if (mid == 0) then
                    n = n + 1
                    mid = n
                    new_coords(:, n - mesh%n_nodes) = 0.5_dp * (mesh%coords(:, a) + &
                                                                mesh%coords(:, b))
                    call edge_table_put(edges, a, b, mid)
                end if
                mids(k, c) = mid
            end do
        end do
        call copy_nodes(mesh, out, st)
        if (st%failed()) return
        do k = mesh%n_nodes + 1, n
            call mesh_add_node(out, fresh_name(out%node_names, 'N', k), &
                               new_coords(:, k - mesh%n_nodes), 0, st)
            if (st%failed()) return
        end do
        do c = 1, mesh%n_cells
            t = mesh%cell_type(c)
            nodes = cell_nodes(mesh, c)
            if (mids(1, c) > 0) then
                nv = CELL_TYPE_CORNERS(t)
                select case (t)
                case (CELL_SEG2)
                    t = CELL_SEG3
                case (CELL_TRIA3)
                    t = CELL_TRIA6
                case default
                    t = CELL_QUAD8
                end select
                nodes = [nodes, mids(1:merge(1, nv, nv == 2), c)]
            end if
            call mesh_add_cell(out, cell_name(mesh, c), t, nodes, mesh%cell_line(c), st)
            if (st%failed()) return
        end do
        call copy_groups(mesh, out, st)
        if (st%ok()) call mesh_finish(out, 0, st)
    end subroutine to_quadratic

    !> QUAD_LINE on the cells flagged in `chosen`.
    !>  converted : out, the cells made linear;  removed : out, the nodes removed
    subroutine to_linear(mesh, chosen, out, converted, removed, st)
        type(mesh_t), intent(in) :: mesh
        logical, intent(in) :: chosen(:)
        type(mesh_t), intent(out) :: out
        integer(i4), intent(out) :: converted, removed
        type(status_t), intent(out) :: st
        logical, allocatable :: in_cell(:), used(:), linear(:)
        integer(i4), allocatable :: new_number(:), nodes(:), members(:)
        integer(i4) :: c, n, k, g, t
        allocate (in_cell(mesh%n_nodes), used(mesh%n_nodes), source=.false.)
        allocate (linear(mesh%n_cells))
        converted = 0
        do c = 1, mesh%n_cells
            t = mesh%cell_type(c)
            linear(c) = chosen(c) .and. cell_type_is_quadratic(t)
            if (linear(c)) converted = converted + 1
            nodes = cell_nodes(mesh, c)
            in_cell(nodes) = .true.
            if (linear(c)) nodes = nodes(1:CELL_TYPE_CORNERS(t))
            used(nodes) = .true.
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
        call mesh_init(out, mesh%dim, mesh%file)
        out%title = mesh%title
        do n = 1, mesh%n_nodes
            if (.not. used(n)) cycle
            if (removed > 0) then
                call mesh_add_node(out, 'N' // to_text(new_number(n)), mesh%coords(:, n), 0, st)
            else
                call mesh_add_node(out, node_name(mesh, n), mesh%coords(:, n), 0, st)
            end if
            if (st%failed()) return
        end do
        do c = 1, mesh%n_cells
            nodes = cell_nodes(mesh, c)
            t = mesh%cell_type(c)
            if (linear(c)) then
                t = CELL_TYPE_LINEAR(t)
                nodes = nodes(1:CELL_TYPE_NODES(t))
            end if
            call mesh_add_cell(out, cell_name(mesh, c), t, new_number(nodes), &
                               mesh%cell_line(c), st)
            if (st%failed()) return
        end do
        do g = 1, n_node_groups(mesh)
            members = nodes_of_group(mesh, g)
            members = new_number(pack(members, used(members)))
            if (size(members) == 0) cycle
            call mesh_add_node_group(out, node_group_name(mesh, g), members, &
                                     mesh%node_group_line(g), st)
            if (st%failed()) return
        end do
        do g = 1, n_cell_groups(mesh)
            call mesh_add_cell_group(out, cell_group_name(mesh, g), cells_of_group(mesh, g), &
                                     mesh%cell_group_line(g), st)
            if (st%failed()) return
        end do
        call mesh_finish(out, 0, st)
    end subroutine to_linear

    ! ---- helpers -------------------------------------------------------------------------

    ! The nodes of `mesh` into `out` (a new mesh of the same dimension and file).
    subroutine copy_nodes(mesh, out, st)
        type(mesh_t), intent(in) :: mesh
        type(mesh_t), intent(out) :: out
        type(status_t), intent(out) :: st
        integer(i4) :: n
        call mesh_init(out, mesh%dim, mesh%file)
        out%title = mesh%title
        do n = 1, mesh%n_nodes
            call mesh_add_node(out, node_name(mesh, n), mesh%coords(:, n), 0, st)
            if (st%failed()) return
        end do
    end subroutine copy_nodes

    ! The cells of `mesh` into `out`, unchanged.
    subroutine copy_cells(mesh, out, st)
        type(mesh_t), intent(in) :: mesh
        type(mesh_t), intent(inout) :: out
        type(status_t), intent(out) :: st
        integer(i4) :: c
        do c = 1, mesh%n_cells
            call mesh_add_cell(out, cell_name(mesh, c), mesh%cell_type(c), &
                               cell_nodes(mesh, c), mesh%cell_line(c), st)
            if (st%failed()) return
        end do
    end subroutine copy_cells

    ! Every group of `mesh` into `out`, members unchanged.
    subroutine copy_groups(mesh, out, st)
        type(mesh_t), intent(in) :: mesh
        type(mesh_t), intent(inout) :: out
        type(status_t), intent(out) :: st
        integer(i4) :: g
        call copy_node_groups(mesh, out, st)
        if (st%failed()) return
        do g = 1, n_cell_groups(mesh)
            call mesh_add_cell_group(out, cell_group_name(mesh, g), cells_of_group(mesh, g), &
                                     mesh%cell_group_line(g), st)
            if (st%failed()) return
        end do
    end subroutine copy_groups

    subroutine copy_node_groups(mesh, out, st)
        type(mesh_t), intent(in) :: mesh
        type(mesh_t), intent(inout) :: out
        type(status_t), intent(out) :: st
        integer(i4) :: g
        do g = 1, n_node_groups(mesh)
            call mesh_add_node_group(out, node_group_name(mesh, g), nodes_of_group(mesh, g), &
                                     mesh%node_group_line(g), st)
            if (st%failed()) return
        end do
    end subroutine copy_node_groups

    function cell_nodes(mesh, c) result(nodes)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c
        integer(i4), allocatable :: nodes(:)
        nodes = mesh%cell_nodes(mesh%cell_ptr(c):mesh%cell_ptr(c + 1) - 1)
    end function cell_nodes

    ! prefix<number>, or prefix<number>_<k> with the smallest k that makes it new.
    function fresh_name(names, prefix, number) result(name)
        type(name_index_t), intent(in) :: names
        character(len=*), intent(in) :: prefix
        integer(i4), intent(in) :: number
        character(len=:), allocatable :: name
        integer(i4) :: k
        name = prefix // to_text(number)
        k = 0
        do while (name_find(names, name) > 0)
            k = k + 1
            name = prefix // to_text(number) // '_' // to_text(k)
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

    subroutine edge_table_init(table, n_nodes, capacity)
        type(edge_table_t), intent(out) :: table
        integer(i4), intent(in) :: n_nodes, capacity
        integer(i8) :: size
        size = 16
        do while (size < 2_i8 * capacity)
            size = 2 * size
        end do
        allocate (table%keys(0:size - 1), source=-1_i8)
        allocate (table%mids(0:size - 1), source=0_i4)
        table%stride = int(n_nodes, i8) + 1
    end subroutine edge_table_init

    ! Slot of the edge (a, b) (either order): its own, or the empty one where it would go.
    integer(i8) function edge_slot(table, a, b) result(slot)
        type(edge_table_t), intent(in) :: table
        integer(i4), intent(in) :: a, b
        integer(i8) :: key, mask
        key = int(min(a, b), i8) * table%stride + int(max(a, b), i8)
        mask = size(table%keys, kind=i8) - 1
        ! spread neighbouring node numbers (each factor < 2**27 and a node number < 2**31:
        ! no overflow)
        slot = iand(ieor(int(min(a, b), i8) * 73856093_i8, int(max(a, b), i8) * 19349663_i8), &
                    mask)
        do while (table%keys(slot) /= -1_i8 .and. table%keys(slot) /= key)
            slot = iand(slot + 1, mask)
        end do
    end function edge_slot

    integer(i4) function edge_table_get(table, a, b) result(mid)
        type(edge_table_t), intent(in) :: table
        integer(i4), intent(in) :: a, b
        mid = table%mids(edge_slot(table, a, b))
    end function edge_table_get

    ! Records the mid node of edge (a, b) (a first one stays). The table was sized for
    ! every edge of every cell at half load.
    subroutine edge_table_put(table, a, b, mid)
        type(edge_table_t), intent(inout) :: table
        integer(i4), intent(in) :: a, b, mid
        integer(i8) :: slot
        slot = edge_slot(table, a, b)
        if (table%keys(slot) /= -1_i8) return
        table%keys(slot) = int(min(a, b), i8) * table%stride + int(max(a, b), i8)
        table%mids(slot) = mid
    end subroutine edge_table_put

end module mesh_create
