!> The mesh: nodes, cells (POI1, SEG2, SEG3, TRIA3, TRIA6, QUAD4, QUAD8, QUAD9; the types
!> and their geometry are in mesh_cell_shapes) in CSR form, named node groups (GROUP_NO)
!> and cell groups (GROUP_MA), with hashed name lookup (layer 4, design.md).
!>
!> Readers build a mesh with `mesh_add_node`, `mesh_add_cell`, `mesh_add_node_group`,
!> `mesh_add_cell_group` and close it with `mesh_finish`; later layers only read it.
module mesh_types
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MESH_ERROR
    use strings, only: to_text
    use mesh_name_index, only: name_index_t, name_add, name_find, name_of, closest_name
    use number_limits, only: MAX_LENGTH, MIN_MESH_EXTENT, is_finite
    use mesh_cell_shapes, only: CELL_POI1, CELL_SEG2, CELL_TRIA3, CELL_QUAD4, CELL_SEG3, &
        CELL_TRIA6, CELL_QUAD8, CELL_QUAD9, N_CELL_TYPES, CELL_TYPE_NAMES, CELL_TYPE_NODES, &
        CELL_TYPE_CORNERS, CELL_TYPE_DIM, CELL_TYPE_LINEAR, CELL_TYPE_ORDER, MAX_CELL_NODES, &
        cell_type_of_name, cell_type_is_quadratic, cell_geometric_measure
    implicit none
    private

    !> Cell types, re-exported from mesh_cell_shapes (users of the mesh take them here).
    public :: CELL_POI1, CELL_SEG2, CELL_TRIA3, CELL_QUAD4, CELL_SEG3, CELL_TRIA6, &
        CELL_QUAD8, CELL_QUAD9, N_CELL_TYPES, CELL_TYPE_NAMES, CELL_TYPE_NODES, &
        CELL_TYPE_CORNERS, CELL_TYPE_DIM, CELL_TYPE_LINEAR, CELL_TYPE_ORDER, MAX_CELL_NODES, &
        cell_type_of_name, cell_type_is_quadratic

    !> Kinds of named entity, for lookups and messages.
    integer(i4), parameter, public :: ENTITY_NODE = 1, ENTITY_CELL = 2, &
        ENTITY_NODE_GROUP = 3, ENTITY_CELL_GROUP = 4
    character(len=8), parameter :: ENTITY_WORDS(4) = ['node    ', 'cell    ', &
        'GROUP_NO', 'GROUP_MA']

    !> A finite-element mesh. Nodes and cells are numbered 1..n in definition order.
    type, public :: mesh_t
        character(len=:), allocatable :: file          !< file it was read from (messages)
        character(len=:), allocatable :: title         !< TITRE text, if any
        integer(i4) :: dim = 0                         !< 2 or 3
        integer(i4) :: n_nodes = 0
        integer(i4) :: n_cells = 0
        real(dp), allocatable :: coords(:, :)          !< (3, n_nodes); z = 0 in 2D
        type(name_index_t) :: node_names
        type(name_index_t) :: cell_names
        integer(i4), allocatable :: cell_type(:)       !< CELL_* per cell
        integer(i4), allocatable :: cell_ptr(:)        !< (n_cells+1): nodes of cell c are
        integer(i4), allocatable :: cell_nodes(:)      !<   cell_nodes(cell_ptr(c):cell_ptr(c+1)-1)
        integer(i4), allocatable :: cell_line(:)       !< file line of each cell (0 unknown)
        type(name_index_t) :: node_group_names
        integer(i4), allocatable :: node_group_ptr(:)  !< CSR of node groups (members)
        integer(i4), allocatable :: node_group_items(:)
        integer(i4), allocatable :: node_group_line(:)
        type(name_index_t) :: cell_group_names
        integer(i4), allocatable :: cell_group_ptr(:)  !< CSR of cell groups (members)
        integer(i4), allocatable :: cell_group_items(:)
        integer(i4), allocatable :: cell_group_line(:)
        integer(i4), private :: n_node_items = 0, n_cell_items = 0
    end type mesh_t

    public :: mesh_init, mesh_add_node, mesh_add_cell, mesh_add_node_group, &
        mesh_add_cell_group, mesh_finish, mesh_release, mesh_remove_node_groups, &
        mesh_remove_cell_groups
    public :: find_node, find_cell, find_node_group, find_cell_group, node_name, cell_name, &
        first_rank_name_conflict, &
        node_group_name, cell_group_name, cells_of_group, nodes_of_group, nodes_of_cells, &
        cell_node_list, cell_measure, cell_centre, mesh_summary, not_found_message, &
        cell_label
    public :: n_node_groups, n_cell_groups

contains

    !> Empties `mesh` and sets its dimension and file name (for messages).
    subroutine mesh_init(mesh, dim, file)
        type(mesh_t), intent(out) :: mesh
        integer(i4), intent(in) :: dim
        character(len=*), intent(in) :: file
        mesh%dim = dim
        mesh%file = file
        mesh%title = ''
        allocate (mesh%coords(3, 1024), mesh%cell_type(1024), mesh%cell_ptr(1025), &
                  mesh%cell_nodes(4096), mesh%cell_line(1024))
        mesh%cell_ptr(1) = 1
        allocate (mesh%node_group_ptr(17), mesh%node_group_items(256), mesh%node_group_line(16))
        allocate (mesh%cell_group_ptr(17), mesh%cell_group_items(256), mesh%cell_group_line(16))
        mesh%node_group_ptr(1) = 1
        mesh%cell_group_ptr(1) = 1
    end subroutine mesh_init

    !> Frees everything `mesh` holds (an empty mesh remains). The deallocation of the dummy
    !> argument's components is generated here, where gfortran generates it completely;
    !> mesh_concept calls it from its final procedure (see there why).
    subroutine mesh_release(mesh)
        type(mesh_t), intent(out) :: mesh
        mesh%n_nodes = 0
    end subroutine mesh_release

    !> Adds a node. Errors (STATUS_MESH_ERROR, at `line`): duplicate name; a coordinate that
    !> is not finite or beyond MAX_LENGTH (number_limits: lengths, areas and element
    !> matrices formed from coordinates must stay finite).
    subroutine mesh_add_node(mesh, name, xyz, line, st)
        type(mesh_t), intent(inout) :: mesh
        character(len=*), intent(in) :: name
        real(dp), intent(in) :: xyz(3)
        integer(i4), intent(in) :: line
        type(status_t), intent(inout) :: st
        integer(i4) :: index, k
        character(len=1), parameter :: AXES(3) = ['X', 'Y', 'Z']
        do k = 1, 3
            if (.not. (is_finite(xyz(k)) .and. abs(xyz(k)) <= MAX_LENGTH)) then
                call set_error(st, STATUS_MESH_ERROR, 'node ' // name // ': coordinate ' // &
                    AXES(k) // ' = ' // to_text(xyz(k)) // ' is out of range (|' // AXES(k) // &
                    '| <= ' // to_text(MAX_LENGTH) // ')', file=mesh%file, line=line)
                return
            end if
        end do
        call name_add(mesh%node_names, name, index)
        if (index < 0) then
            call set_error(st, STATUS_MESH_ERROR, 'duplicate node name ' // name, &
                           file=mesh%file, line=line)
            return
        end if
        if (index > size(mesh%coords, 2)) call grow_real2(mesh%coords, 2 * index)
        mesh%coords(:, index) = xyz
        mesh%n_nodes = index
    end subroutine mesh_add_node

    !> Adds a cell of type `ctype` on nodes `nodes` (node numbers). Errors: duplicate name,
    !> wrong node count for the type.
    subroutine mesh_add_cell(mesh, name, ctype, nodes, line, st)
        type(mesh_t), intent(inout) :: mesh
        character(len=*), intent(in) :: name
        integer(i4), intent(in) :: ctype, nodes(:), line
        type(status_t), intent(inout) :: st
        integer(i4) :: index, p
        if (size(nodes) /= CELL_TYPE_NODES(ctype)) then
            call set_error(st, STATUS_MESH_ERROR, 'cell ' // name // ' has ' // &
                to_text(size(nodes, kind=i4)) // ' nodes, a ' // trim(CELL_TYPE_NAMES(ctype)) &
                // ' has ' // to_text(CELL_TYPE_NODES(ctype)), file=mesh%file, line=line)
            return
        end if
        call name_add(mesh%cell_names, name, index)
        if (index < 0) then
            call set_error(st, STATUS_MESH_ERROR, 'duplicate cell name ' // name, &
                           file=mesh%file, line=line)
            return
        end if
        if (index + 1 > size(mesh%cell_ptr)) then
            call grow_int(mesh%cell_ptr, 2 * index + 1)
            call grow_int(mesh%cell_type, 2 * index)
            call grow_int(mesh%cell_line, 2 * index)
        end if
        p = mesh%cell_ptr(index)
        if (p + size(nodes) > size(mesh%cell_nodes)) call grow_int(mesh%cell_nodes, &
            2 * (p + size(nodes)))
        mesh%cell_nodes(p:p + size(nodes) - 1) = nodes
        mesh%cell_ptr(index + 1) = p + size(nodes, kind=i4)
        mesh%cell_type(index) = ctype
        mesh%cell_line(index) = line
        mesh%n_cells = index
    end subroutine mesh_add_cell

    !> Adds a GROUP_NO with member node numbers. Errors: duplicate group name.
    subroutine mesh_add_node_group(mesh, name, members, line, st)
        type(mesh_t), intent(inout) :: mesh
        character(len=*), intent(in) :: name
        integer(i4), intent(in) :: members(:), line
        type(status_t), intent(inout) :: st
        call add_group(mesh%node_group_names, mesh%node_group_ptr, mesh%node_group_items, &
            mesh%node_group_line, mesh%n_node_items, 'GROUP_NO', name, members, line, &
            mesh%file, st)
    end subroutine mesh_add_node_group

    !> Adds a GROUP_MA with member cell numbers. Errors: duplicate group name.
    subroutine mesh_add_cell_group(mesh, name, members, line, st)
        type(mesh_t), intent(inout) :: mesh
        character(len=*), intent(in) :: name
        integer(i4), intent(in) :: members(:), line
        type(status_t), intent(inout) :: st
        call add_group(mesh%cell_group_names, mesh%cell_group_ptr, mesh%cell_group_items, &
            mesh%cell_group_line, mesh%n_cell_items, 'GROUP_MA', name, members, line, &
            mesh%file, st)
    end subroutine mesh_add_cell_group

    subroutine add_group(names, ptr, items, lines, n_items, word, name, members, line, &
                         file, st)
        type(name_index_t), intent(inout) :: names
        integer(i4), allocatable, intent(inout) :: ptr(:), items(:), lines(:)
        integer(i4), intent(inout) :: n_items
        character(len=*), intent(in) :: word, name, file
        integer(i4), intent(in) :: members(:), line
        type(status_t), intent(inout) :: st
        integer(i4) :: index
        call name_add(names, name, index)
        if (index < 0) then
            call set_error(st, STATUS_MESH_ERROR, 'duplicate ' // word // ' name ' // name, &
                           file=file, line=line)
            return
        end if
        if (index + 1 > size(ptr)) then
            call grow_int(ptr, 2 * index + 1)
            call grow_int(lines, 2 * index)
        end if
        if (n_items + size(members) > size(items)) call grow_int(items, &
            2 * (n_items + size(members)))
        items(n_items + 1:n_items + size(members)) = members
        n_items = n_items + size(members, kind=i4)
        ptr(index + 1) = n_items + 1
        lines(index) = line
    end subroutine add_group

    !> Removes the GROUP_NO whose flag `remove(g)` is set (DEFI_GROUP/DETR_GROUP_NO); the
    !> others keep their order, members and lines. O(groups + members).
    subroutine mesh_remove_node_groups(mesh, remove)
        type(mesh_t), intent(inout) :: mesh
        logical, intent(in) :: remove(:)
        call remove_groups(mesh%node_group_names, mesh%node_group_ptr, &
            mesh%node_group_items, mesh%node_group_line, mesh%n_node_items, remove)
    end subroutine mesh_remove_node_groups

    !> Removes the GROUP_MA whose flag `remove(g)` is set (DEFI_GROUP/DETR_GROUP_MA).
    subroutine mesh_remove_cell_groups(mesh, remove)
        type(mesh_t), intent(inout) :: mesh
        logical, intent(in) :: remove(:)
        call remove_groups(mesh%cell_group_names, mesh%cell_group_ptr, &
            mesh%cell_group_items, mesh%cell_group_line, mesh%n_cell_items, remove)
    end subroutine mesh_remove_cell_groups

    ! Rebuilds a group family without the flagged groups (the name index cannot delete:
    ! the kept names are added again to a new one).
    subroutine remove_groups(names, ptr, items, lines, n_items, remove)
        type(name_index_t), intent(inout) :: names
        integer(i4), allocatable, intent(inout) :: ptr(:), items(:), lines(:)
        integer(i4), intent(inout) :: n_items
        logical, intent(in) :: remove(:)
        type(name_index_t) :: kept
        integer(i4), allocatable :: new_ptr(:), new_items(:), new_lines(:)
        integer(i4) :: g, n, index, first, last
        n = names%count
        allocate (new_ptr(n + 1), new_items(n_items), new_lines(max(n, 1)))
        new_ptr(1) = 1
        do g = 1, n
            if (remove(g)) cycle
            call name_add(kept, name_of(names, g), index)
            first = ptr(g)
            last = ptr(g + 1) - 1
            new_items(new_ptr(index):new_ptr(index) + last - first) = items(first:last)
            new_ptr(index + 1) = new_ptr(index) + last - first + 1
            new_lines(index) = lines(g)
        end do
        n_items = new_ptr(kept%count + 1) - 1
        names = kept
        call move_alloc(new_ptr, ptr)
        call move_alloc(new_items, items)
        call move_alloc(new_lines, lines)
    end subroutine remove_groups

    !> Trims the work arrays to their final sizes and checks the mesh is not empty.
    !> Errors: no nodes or no cells ("empty mesh").
    !>  check_cells : optional, default true: false skips the degenerate-cell check, for a
    !>                mesh made from a checked one without changing any cell's geometry
    !>                (CREA_MAILLAGE's LINE_QUAD, QUAD8_9, QUAD_LINE, CREA_POI1, CREA_MAILLE)
    subroutine mesh_finish(mesh, line, st, check_cells)
        type(mesh_t), intent(inout) :: mesh
        integer(i4), intent(in) :: line
        type(status_t), intent(inout) :: st
        logical, intent(in), optional :: check_cells
        logical :: check
        if (mesh%n_nodes == 0 .or. mesh%n_cells == 0) then
            call set_error(st, STATUS_MESH_ERROR, 'empty mesh: ' // to_text(mesh%n_nodes) // &
                ' nodes and ' // to_text(mesh%n_cells) // ' cells (a mesh needs both)', &
                file=mesh%file, line=line)
            return
        end if
        check = .true.
        if (present(check_cells)) check = check_cells
        if (check) call check_degenerate_cells(mesh, st)
        if (st%failed()) return
        call shrink_real2(mesh%coords, mesh%n_nodes)
        call shrink_int(mesh%cell_type, mesh%n_cells)
        call shrink_int(mesh%cell_line, mesh%n_cells)
        call shrink_int(mesh%cell_ptr, mesh%n_cells + 1)
        call shrink_int(mesh%cell_nodes, mesh%cell_ptr(mesh%n_cells + 1) - 1)
        call shrink_int(mesh%node_group_ptr, n_node_groups(mesh) + 1)
        call shrink_int(mesh%node_group_line, n_node_groups(mesh))
        call shrink_int(mesh%node_group_items, mesh%n_node_items)
        call shrink_int(mesh%cell_group_ptr, n_cell_groups(mesh) + 1)
        call shrink_int(mesh%cell_group_line, n_cell_groups(mesh))
        call shrink_int(mesh%cell_group_items, mesh%n_cell_items)
    end subroutine mesh_finish

    ! A line or surface cell whose measure is negligible against the mesh size is an error
    ! (its element matrices and RIGI_PARASOL shares would be meaningless); so is a QUAD4 or
    ! a quadratic cell with two of its nodes at one place (collapsed: the area test may
    ! pass, a triangle's, while the isoparametric map is singular there).
    subroutine check_degenerate_cells(mesh, st)
        type(mesh_t), intent(inout) :: mesh
        type(status_t), intent(inout) :: st
        real(dp), parameter :: RELATIVE_TOLERANCE = 1.0e-12_dp
        real(dp) :: size_scale, threshold
        integer(i4) :: c, ctype
        size_scale = maxval(maxval(mesh%coords(:, 1:mesh%n_nodes), dim=2) &
                            - minval(mesh%coords(:, 1:mesh%n_nodes), dim=2))
        if (size_scale < MIN_MESH_EXTENT .and. any(mesh%cell_type(1:mesh%n_cells) /= &
                                                   CELL_POI1)) then
            c = findloc(mesh%cell_type(1:mesh%n_cells) /= CELL_POI1, .true., dim=1)
            call set_error(st, STATUS_MESH_ERROR, 'the mesh spans ' // to_text(size_scale) // &
                ' (largest side of its bounding box), less than ' // to_text(MIN_MESH_EXTENT) &
                // ': cell ' // cell_name(mesh, c) // ' and the others are too small to ' // &
                'compute with (change the length unit)', file=mesh%file, line=mesh%cell_line(c))
            return
        end if
        do c = 1, mesh%n_cells
            ctype = mesh%cell_type(c)
            select case (CELL_TYPE_DIM(ctype))
            case (1)
                threshold = RELATIVE_TOLERANCE * size_scale
            case (2)
                threshold = RELATIVE_TOLERANCE * size_scale**2
            case default
                cycle
            end select
            if (ctype == CELL_QUAD4 .or. cell_type_is_quadratic(ctype)) then
                call check_distinct_nodes(c, RELATIVE_TOLERANCE * size_scale)
                if (st%failed()) return
            end if
            if (cell_measure(mesh, c) <= threshold) then
                call set_error(st, STATUS_MESH_ERROR, 'degenerate cell ' // cell_name(mesh, c) &
                    // ': its ' // trim(CELL_TYPE_NAMES(ctype)) // ' has zero ' // &
                    trim(merge('length', 'area  ', CELL_TYPE_DIM(ctype) == 1)), &
                    file=mesh%file, line=mesh%cell_line(c))
                return
            end if
        end do
    contains
        ! Two nodes of cell c closer than `tolerance` (or the same node twice).
        subroutine check_distinct_nodes(c, tolerance)
            integer(i4), intent(in) :: c
            real(dp), intent(in) :: tolerance
            integer(i4) :: i, j, p0, nn
            character(len=:), allocatable :: need, what
            p0 = mesh%cell_ptr(c) - 1
            nn = mesh%cell_ptr(c + 1) - mesh%cell_ptr(c)
            if (mesh%cell_type(c) == CELL_QUAD4) then
                need = ' (a QUAD4 needs four distinct corners)'
                what = 'corner'
            else
                need = ' (a ' // trim(CELL_TYPE_NAMES(mesh%cell_type(c))) // ' needs ' // &
                    to_text(nn) // ' distinct nodes)'
                what = 'node'
            end if
            do i = 1, nn - 1
                do j = i + 1, nn
                    if (norm2(mesh%coords(:, mesh%cell_nodes(p0 + i)) - &
                              mesh%coords(:, mesh%cell_nodes(p0 + j))) > tolerance) cycle
                    if (mesh%cell_nodes(p0 + i) == mesh%cell_nodes(p0 + j)) then
                        call set_error(st, STATUS_MESH_ERROR, 'cell ' // cell_name(mesh, c) // &
                            ': node ' // node_name(mesh, mesh%cell_nodes(p0 + i)) // &
                            ' is ' // what // ' ' // to_text(i) // ' and ' // what // ' ' // &
                            to_text(j) // need, file=mesh%file, line=mesh%cell_line(c))
                    else
                        call set_error(st, STATUS_MESH_ERROR, 'cell ' // cell_name(mesh, c) // &
                            ': its ' // what // 's ' // &
                            node_name(mesh, mesh%cell_nodes(p0 + i)) // ' and ' // &
                            node_name(mesh, mesh%cell_nodes(p0 + j)) // ' coincide' // need, &
                            file=mesh%file, line=mesh%cell_line(c))
                    end if
                    return
                end do
            end do
        end subroutine check_distinct_nodes
    end subroutine check_degenerate_cells

    !> Number of GROUP_NO / GROUP_MA.
    integer(i4) function n_node_groups(mesh)
        type(mesh_t), intent(in) :: mesh
        n_node_groups = mesh%node_group_names%count
    end function n_node_groups

    integer(i4) function n_cell_groups(mesh)
        type(mesh_t), intent(in) :: mesh
        n_cell_groups = mesh%cell_group_names%count
    end function n_cell_groups

    !> Number of the node named `name`. Errors: no such node (with a did-you-mean).
    integer(i4) function find_node(mesh, name, st) result(index)
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: name
        type(status_t), intent(inout) :: st
        index = find_entity(mesh, mesh%node_names, ENTITY_NODE, name, st)
    end function find_node

    !> Number of the cell named `name`. Errors: no such cell.
    integer(i4) function find_cell(mesh, name, st) result(index)
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: name
        type(status_t), intent(inout) :: st
        index = find_entity(mesh, mesh%cell_names, ENTITY_CELL, name, st)
    end function find_cell

    !> Number of the GROUP_NO named `name`. Errors: no such group.
    integer(i4) function find_node_group(mesh, name, st) result(index)
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: name
        type(status_t), intent(inout) :: st
        index = find_entity(mesh, mesh%node_group_names, ENTITY_NODE_GROUP, name, st)
    end function find_node_group

    !> Number of the GROUP_MA named `name`. Errors: no such group.
    integer(i4) function find_cell_group(mesh, name, st) result(index)
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: name
        type(status_t), intent(inout) :: st
        index = find_entity(mesh, mesh%cell_group_names, ENTITY_CELL_GROUP, name, st)
    end function find_cell_group

    integer(i4) function find_entity(mesh, names, kind, name, st) result(index)
        type(mesh_t), intent(in) :: mesh
        type(name_index_t), intent(in) :: names
        integer(i4), intent(in) :: kind
        character(len=*), intent(in) :: name
        type(status_t), intent(inout) :: st
        index = 0
        if (kind == ENTITY_NODE) index = entity_by_number(name, mesh%n_nodes)
        if (kind == ENTITY_CELL) index = entity_by_number(name, mesh%n_cells)
        if (index == 0) index = name_find(names, name)
        if (index == 0) call set_error(st, STATUS_MESH_ERROR, &
            not_found_message(mesh, names, kind, name))
    end function find_entity

    !> A node or cell named by its number, as code_aster 17 reads NOEUD= / MAILLE= (its
    !> char8_to_int: 'N19', 'M19' or '19' is entity 19, its meshes keeping no names, a .mail
    !> file's dropped by lrmast): the number when `name` is N or M and digits, or digits
    !> alone, within 1 .. n; 0 otherwise (the name is then looked up among the file's).
    pure integer(i4) function entity_by_number(name, n) result(index)
        character(len=*), intent(in) :: name
        integer(i4), intent(in) :: n
        integer :: first, k, value
        index = 0
        first = 1
        if (len(name) >= 1) then
            if (name(1:1) == 'N' .or. name(1:1) == 'M') first = 2
        end if
        if (len(name) < first .or. len(name) - first + 1 > 8) return
        value = 0
        do k = first, len(name)
            if (name(k:k) < '0' .or. name(k:k) > '9') return
            value = 10 * value + (ichar(name(k:k)) - ichar('0'))
        end do
        if (value >= 1 .and. value <= n) index = int(value, i4)
    end function entity_by_number

    !> The first node (which = 'N') or cell ('M') whose file name reads as another entity's
    !> number (entity_by_number: the file names node 4 'N5', which a deck's NOEUD='N5'
    !> means node 5 by): its rank and name; rank 0 when there is none.
    subroutine first_rank_name_conflict(mesh, which, rank, name)
        type(mesh_t), intent(in) :: mesh
        character, intent(in) :: which
        integer(i4), intent(out) :: rank
        character(len=:), allocatable, intent(out) :: name
        integer(i4) :: j, n, k
        rank = 0
        n = mesh%n_nodes
        if (which == 'M') n = mesh%n_cells
        do j = 1, n
            if (which == 'M') then
                name = cell_name(mesh, j)
            else
                name = node_name(mesh, j)
            end if
            k = entity_by_number(name, n)
            if (k /= 0 .and. k /= j) then
                rank = j
                return
            end if
        end do
        name = ''
    end subroutine first_rank_name_conflict

    !> "no node named X in mesh.mail (did you mean Y?)" for entity kind ENTITY_*.
    function not_found_message(mesh, names, kind, name) result(text)
        type(mesh_t), intent(in) :: mesh
        type(name_index_t), intent(in) :: names
        integer(i4), intent(in) :: kind
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: text, hint
        text = 'no ' // trim(ENTITY_WORDS(kind)) // ' named ' // name
        if (allocated(mesh%file)) text = text // ' in ' // mesh%file
        hint = closest_name(names, name)
        if (len(hint) > 0) text = text // ' (did you mean ' // hint // '?)'
    end function not_found_message

    !> "cell M12 (GROUP_MA DALLE)" for messages: the cell's name and the first GROUP_MA
    !> holding it (`group` when given, else searched; omitted when the cell is in none).
    function cell_label(mesh, c, group) result(text)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c
        character(len=*), intent(in), optional :: group
        character(len=:), allocatable :: text
        integer(i4) :: g
        text = 'cell ' // cell_name(mesh, c)
        if (present(group)) then
            if (len(group) > 0) then
                text = text // ' (GROUP_MA ' // group // ')'
                return
            end if
        end if
        do g = 1, n_cell_groups(mesh)
            if (any(mesh%cell_group_items(mesh%cell_group_ptr(g):mesh%cell_group_ptr(g + 1) &
                                          - 1) == c)) then
                text = text // ' (GROUP_MA ' // cell_group_name(mesh, g) // ')'
                return
            end if
        end do
    end function cell_label

    !> Names of node / cell / group number `i`.
    function node_name(mesh, i) result(name)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: i
        character(len=:), allocatable :: name
        name = name_of(mesh%node_names, i)
    end function node_name

    function cell_name(mesh, i) result(name)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: i
        character(len=:), allocatable :: name
        name = name_of(mesh%cell_names, i)
    end function cell_name

    function node_group_name(mesh, i) result(name)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: i
        character(len=:), allocatable :: name
        name = name_of(mesh%node_group_names, i)
    end function node_group_name

    function cell_group_name(mesh, i) result(name)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: i
        character(len=:), allocatable :: name
        name = name_of(mesh%cell_group_names, i)
    end function cell_group_name

    !> Cells of GROUP_MA number `g` (in group order); empty if g is not a group number (so
    !> `cells_of_group(mesh, find_cell_group(mesh, name, st))` is safe; check st).
    function cells_of_group(mesh, g) result(cells)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: g
        integer(i4), allocatable :: cells(:)
        if (g < 1 .or. g > n_cell_groups(mesh)) then
            allocate (cells(0))
            return
        end if
        cells = mesh%cell_group_items(mesh%cell_group_ptr(g):mesh%cell_group_ptr(g + 1) - 1)
    end function cells_of_group

    !> Nodes of GROUP_NO number `g` (in group order); empty if g is not a group number.
    function nodes_of_group(mesh, g) result(nodes)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: g
        integer(i4), allocatable :: nodes(:)
        if (g < 1 .or. g > n_node_groups(mesh)) then
            allocate (nodes(0))
            return
        end if
        nodes = mesh%node_group_items(mesh%node_group_ptr(g):mesh%node_group_ptr(g + 1) - 1)
    end function nodes_of_group

    !> Node numbers of cell `c`.
    function cell_node_list(mesh, c) result(nodes)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c
        integer(i4), allocatable :: nodes(:)
        nodes = mesh%cell_nodes(mesh%cell_ptr(c):mesh%cell_ptr(c + 1) - 1)
    end function cell_node_list

    !> Distinct nodes of a list of cells, in increasing node number.
    function nodes_of_cells(mesh, cells) result(nodes)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:)
        integer(i4), allocatable :: nodes(:)
        logical, allocatable :: used(:)
        integer(i4) :: i, n
        allocate (used(mesh%n_nodes), source=.false.)
        do i = 1, size(cells)
            used(mesh%cell_nodes(mesh%cell_ptr(cells(i)):mesh%cell_ptr(cells(i) + 1) - 1)) &
                = .true.
        end do
        nodes = pack([(n, n = 1, mesh%n_nodes)], used)
    end function nodes_of_cells

    !> Measure of cell `c`: 0 for POI1, length for SEG2, area for TRIA3 (half the cross
    !> product) and QUAD4 (2 x 2 Gauss integration of |x_xi x x_eta| over the bilinear
    !> surface, exact for a plane quadrilateral, accurate for a warped one); quadratic cells
    !> by mesh_cell_shapes' cell_geometric_measure (exact for straight-sided plane cells).
    real(dp) function cell_measure(mesh, c) result(measure)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c
        real(dp) :: x(3, MAX_CELL_NODES), dxi(3), deta(3), xi, eta
        real(dp), parameter :: g = 0.577350269189625764509148780502_dp  ! 1/sqrt(3)
        integer(i4) :: n, i, j
        n = mesh%cell_ptr(c + 1) - mesh%cell_ptr(c)
        x(:, 1:n) = mesh%coords(:, mesh%cell_nodes(mesh%cell_ptr(c):mesh%cell_ptr(c + 1) - 1))
        select case (mesh%cell_type(c))
        case (CELL_SEG2)
            measure = norm2(x(:, 2) - x(:, 1))
        case (CELL_TRIA3)
            measure = 0.5_dp * norm2(cross(x(:, 2) - x(:, 1), x(:, 3) - x(:, 1)))
        case (CELL_QUAD4)
            measure = 0.0_dp
            do j = -1, 1, 2
                do i = -1, 1, 2
                    xi = i * g
                    eta = j * g
                    dxi = 0.25_dp * ((1.0_dp - eta) * (x(:, 2) - x(:, 1)) &
                                     + (1.0_dp + eta) * (x(:, 3) - x(:, 4)))
                    deta = 0.25_dp * ((1.0_dp - xi) * (x(:, 4) - x(:, 1)) &
                                      + (1.0_dp + xi) * (x(:, 3) - x(:, 2)))
                    measure = measure + norm2(cross(dxi, deta))   ! weight 1 per point
                end do
            end do
        case (CELL_SEG3, CELL_TRIA6, CELL_QUAD8, CELL_QUAD9)
            measure = cell_geometric_measure(mesh%cell_type(c), x(:, 1:n))
        case default
            measure = 0.0_dp
        end select
    end function cell_measure

    !> Centroid of the nodes of cell `c`.
    function cell_centre(mesh, c) result(centre)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c
        real(dp) :: centre(3)
        integer(i4) :: p0, p1
        p0 = mesh%cell_ptr(c)
        p1 = mesh%cell_ptr(c + 1) - 1
        centre = sum(mesh%coords(:, mesh%cell_nodes(p0:p1)), dim=2) / real(p1 - p0 + 1, dp)
    end function cell_centre

    pure function cross(a, b) result(c)
        real(dp), intent(in) :: a(3), b(3)
        real(dp) :: c(3)
        c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
    end function cross

    !> Summary for the .mess file: nodes, cells per type, groups with sizes, bounding box.
    function mesh_summary(mesh) result(lines)
        type(mesh_t), intent(in) :: mesh
        character(len=100), allocatable :: lines(:)
        integer(i4) :: t, g, k, k_type, n_of_type
        character(len=100) :: buf
        allocate (lines(6 + N_CELL_TYPES + n_node_groups(mesh) + n_cell_groups(mesh)))
        k = 0
        call put('MESH ' // mesh%file // ' (dimension ' // to_text(mesh%dim) // ')')
        call put('  nodes          ' // to_text(mesh%n_nodes))
        call put('  cells          ' // to_text(mesh%n_cells))
        do k_type = 1, N_CELL_TYPES          ! the types present, in Code_Aster's order
            t = CELL_TYPE_ORDER(k_type)
            n_of_type = count(mesh%cell_type(1:mesh%n_cells) == t, kind=i4)
            if (n_of_type > 0) call put('    ' // CELL_TYPE_NAMES(t) // '        ' // &
                                        to_text(n_of_type))
        end do
        do g = 1, n_node_groups(mesh)
            call put('  GROUP_NO ' // node_group_name(mesh, g) // ' ' // &
                to_text(mesh%node_group_ptr(g + 1) - mesh%node_group_ptr(g)) // ' nodes')
        end do
        do g = 1, n_cell_groups(mesh)
            call put('  GROUP_MA ' // cell_group_name(mesh, g) // ' ' // &
                to_text(mesh%cell_group_ptr(g + 1) - mesh%cell_group_ptr(g)) // ' cells')
        end do
        write (buf, '(a,3(1x,es12.5))') '  bounding box min', minval(mesh%coords, dim=2)
        call put(buf)
        write (buf, '(a,3(1x,es12.5))') '  bounding box max', maxval(mesh%coords, dim=2)
        call put(buf)
        lines = lines(1:k)
    contains
        subroutine put(text)
            character(len=*), intent(in) :: text
            k = k + 1
            lines(k) = text
        end subroutine put
    end function mesh_summary

    subroutine grow_int(a, n)
        integer(i4), allocatable, intent(inout) :: a(:)
        integer(i4), intent(in) :: n
        integer(i4), allocatable :: b(:)
        allocate (b(n))
        b(1:size(a)) = a
        call move_alloc(b, a)
    end subroutine grow_int

    subroutine shrink_int(a, n)
        integer(i4), allocatable, intent(inout) :: a(:)
        integer(i4), intent(in) :: n
        integer(i4), allocatable :: b(:)
        b = a(1:n)
        call move_alloc(b, a)
    end subroutine shrink_int

    subroutine grow_real2(a, n)
        real(dp), allocatable, intent(inout) :: a(:, :)
        integer(i4), intent(in) :: n
        real(dp), allocatable :: b(:, :)
        allocate (b(3, n))
        b(:, 1:size(a, 2)) = a
        call move_alloc(b, a)
    end subroutine grow_real2

    subroutine shrink_real2(a, n)
        real(dp), allocatable, intent(inout) :: a(:, :)
        integer(i4), intent(in) :: n
        real(dp), allocatable :: b(:, :)
        b = a(:, 1:n)
        call move_alloc(b, a)
    end subroutine shrink_real2

end module mesh_types
