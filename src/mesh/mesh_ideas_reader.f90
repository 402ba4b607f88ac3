!> Reader of I-DEAS universal files (LIRE_MAILLAGE FORMAT='IDEAS', Code_Aster U7.01.01 and
!> its PRE_IDEAS conversion): datasets separated by lines `-1`, each opened by its number.
!>  2411  nodes: `label csys dcsys color` then `x y z` (D or E exponents);
!>  2412  elements: `label fe_id phys mat color n_nodes`, for the beam descriptors (11, 21,
!>        22, 23, 24) one line of orientation data, then the node labels;
!>  2435, 2452, 2467, 2477  groups: a header line whose last integer is the number of
!>        entities, the group's name, then four integers per entity (type, label, 0, 0):
!>        type 7 a node (the group becomes a GROUP_NO), 8 an element (a GROUP_MA).
!> Other datasets (header 151, units 164, coordinate systems 2420 ...) are skipped. Nodes
!> are named N<label>, cells M<label>, as PRE_IDEAS names them; the coordinates are kept
!> in 3D (COOR_3D). Element descriptors, as I-DEAS numbers them: rods and beams 11, 21 ->
!> SEG2, parabolic beams 22, 24 -> SEG3; linear triangles 41, 51, 61, 74, 81, 91 -> TRIA3,
!> parabolic 42, 52, 62, 72, 82, 92 -> TRIA6; linear quadrangles 44, 54, 64, 71, 84, 94 ->
!> QUAD4, parabolic 45, 55, 65, 75, 85, 95 -> QUAD8; lumped mass 161 -> POI1. I-DEAS lists
!> a quadratic cell's nodes around it (corner, middle, corner ...): they are reordered to
!> Code_Aster's corners first. Any other descriptor is an error naming it.
!>
!> Nothing read is taken on trust (issue 13): counts are checked against the bytes left,
!> labels looked up through the names (an unknown node or cell label is an error at its
!> line), every number parsed by the lexer's checked parsers.
module mesh_ideas_reader
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MESH_ERROR
    use strings, only: to_text
    use mesh_types, only: mesh_t, mesh_init, mesh_add_node, mesh_add_cell, &
        mesh_add_node_group, mesh_add_cell_group, mesh_finish, CELL_POI1, CELL_SEG2, &
        CELL_TRIA3, CELL_QUAD4, CELL_SEG3, CELL_TRIA6, CELL_QUAD8
    use mesh_name_index, only: name_find
    use mesh_text_lexer, only: text_lexer_t, open_lexer, next_token, next_line, at_end, &
        parse_real, parse_integer, bytes_left
    implicit none
    private

    public :: read_ideas_mesh

    !> Largest number of nodes an element may list (a parabolic quadrangle: 8).
    integer(i4), parameter :: MAX_ELEMENT_NODES = 8

contains

    !> Reads the universal file `path` into `mesh`.
    !>  st : out, STATUS_IO_ERROR if unreadable; STATUS_MESH_ERROR with file and line for a
    !>       bad number, an element descriptor not read, an unknown node or element label,
    !>       a count beyond what the file holds, a duplicate name, an empty or degenerate mesh
    subroutine read_ideas_mesh(path, mesh, st)
        character(len=*), intent(in) :: path
        type(mesh_t), intent(out) :: mesh
        type(status_t), intent(out) :: st
        type(text_lexer_t) :: lex
        integer(i4) :: first, last, dataset
        logical :: ok
        call open_lexer(lex, path, st)
        if (st%failed()) return
        lex%percent_comments = .false.
        call mesh_init(mesh, 3_i4, path)
        do while (.not. at_end(lex))
            call next_token(lex, first, last)
            if (first == 0) then
                call next_line(lex)
                cycle
            end if
            if (lex%text(first:last) /= '-1') then
                call set_error(st, STATUS_MESH_ERROR, 'expected -1 (the start of a ' // &
                    'dataset), got ' // lex%text(first:min(last, first + 31)) // &
                    ': not an I-DEAS universal file', file=path, line=lex%line)
                return
            end if
            call next_line(lex)
            call next_token(lex, first, last)
            if (first == 0) exit                      ! a trailing -1
            call parse_integer(lex%text(first:last), dataset, ok)
            if (.not. ok) then
                call set_error(st, STATUS_MESH_ERROR, 'expected a dataset number, got ' // &
                    lex%text(first:min(last, first + 31)), file=path, line=lex%line)
                return
            end if
            call next_line(lex)
            select case (dataset)
            case (2411)
                call read_nodes(lex, mesh, st)
            case (2412)
                call read_elements(lex, mesh, st)
            case (2435, 2452, 2467, 2477)
                call read_groups(lex, mesh, st)
            case default
                call skip_dataset(lex)
            end select
            if (st%failed()) then
                if (.not. allocated(st%file)) st%file = path
                if (st%line == 0) st%line = lex%line
                return
            end if
        end do
        call mesh_finish(mesh, lex%line, st)
    end subroutine read_ideas_mesh

    ! True (and the line left as it is) when the current line is the `-1` closing a dataset.
    logical function at_dataset_end(lex)
        type(text_lexer_t), intent(inout) :: lex
        integer(i4) :: first, last, saved
        saved = lex%pos
        call next_token(lex, first, last)
        at_dataset_end = at_end(lex) .and. first == 0
        if (first > 0) at_dataset_end = lex%text(first:last) == '-1'
        lex%pos = saved
    end function at_dataset_end

    ! Skips to the line after the `-1` closing the dataset.
    subroutine skip_dataset(lex)
        type(text_lexer_t), intent(inout) :: lex
        do while (.not. at_end(lex))
            if (at_dataset_end(lex)) then
                call next_line(lex)
                return
            end if
            call next_line(lex)
        end do
    end subroutine skip_dataset

    ! The integers of the current line (at most size(values)); n how many; the lexer moves
    ! to the next line.
    subroutine line_integers(lex, values, n, st)
        type(text_lexer_t), intent(inout) :: lex
        integer(i4), intent(out) :: values(:), n
        type(status_t), intent(out) :: st
        integer(i4) :: first, last
        logical :: ok
        n = 0
        do
            call next_token(lex, first, last)
            if (first == 0) exit
            if (n == size(values)) then
                call set_error(st, STATUS_MESH_ERROR, 'more than ' // to_text(size(values)) // &
                    ' integers on the line', line=lex%line)
                return
            end if
            n = n + 1
            call parse_integer(lex%text(first:last), values(n), ok)
            if (.not. ok) then
                call set_error(st, STATUS_MESH_ERROR, 'expected an integer, got ' // &
                    lex%text(first:min(last, first + 31)), line=lex%line)
                return
            end if
        end do
        call next_line(lex)
    end subroutine line_integers

    ! Dataset 2411.
    subroutine read_nodes(lex, mesh, st)
        type(text_lexer_t), intent(inout) :: lex
        type(mesh_t), intent(inout) :: mesh
        type(status_t), intent(out) :: st
        integer(i4) :: head(8), n, k, first, last, line
        real(dp) :: xyz(3)
        logical :: ok, too_big
        do while (.not. at_dataset_end(lex))
            line = lex%line
            call line_integers(lex, head, n, st)
            if (st%failed()) return
            if (n /= 4) then
                call set_error(st, STATUS_MESH_ERROR, 'a node record starts with 4 ' // &
                    'integers (label, coordinate systems, color), got ' // to_text(n), &
                    line=line)
                return
            end if
            do k = 1, 3
                call next_token(lex, first, last)
                if (first == 0) then
                    call set_error(st, STATUS_MESH_ERROR, 'node ' // to_text(head(1)) // &
                        ': expected 3 coordinates', line=lex%line)
                    return
                end if
                call parse_real(lex%text(first:last), xyz(k), ok, too_big)
                if (.not. ok) then
                    call set_error(st, STATUS_MESH_ERROR, 'node ' // to_text(head(1)) // &
                        ': bad coordinate ' // lex%text(first:min(last, first + 31)), &
                        line=lex%line)
                    return
                end if
            end do
            call mesh_add_node(mesh, 'N' // to_text(head(1)), xyz, lex%line, st)
            if (st%failed()) return
            call next_line(lex)
        end do
        call next_line(lex)
    end subroutine read_nodes

    ! Dataset 2412.
    subroutine read_elements(lex, mesh, st)
        type(text_lexer_t), intent(inout) :: lex
        type(mesh_t), intent(inout) :: mesh
        type(status_t), intent(out) :: st
        integer(i4) :: head(8), labels(MAX_ELEMENT_NODES), nodes(MAX_ELEMENT_NODES), &
            extra(8), n, got, k, ctype, line
        integer(i4), allocatable :: order(:)
        do while (.not. at_dataset_end(lex))
            line = lex%line
            call line_integers(lex, head, n, st)
            if (st%failed()) return
            if (n /= 6) then
                call set_error(st, STATUS_MESH_ERROR, 'an element record starts with 6 ' // &
                    'integers (label, descriptor, properties, color, node count), got ' // &
                    to_text(n), line=line)
                return
            end if
            call cell_kind(head(2), ctype, order)
            if (ctype == 0) then
                call set_error(st, STATUS_MESH_ERROR, 'element ' // to_text(head(1)) // &
                    ': I-DEAS descriptor ' // to_text(head(2)) // ' is not read by ' // &
                    'parasol (beams, rods, shells, plane triangles and quadrangles, ' // &
                    'lumped masses are)', line=line)
                return
            end if
            if (head(6) /= size(order)) then
                call set_error(st, STATUS_MESH_ERROR, 'element ' // to_text(head(1)) // &
                    ': descriptor ' // to_text(head(2)) // ' has ' // to_text(size(order)) // &
                    ' nodes, the record says ' // to_text(head(6)), line=line)
                return
            end if
            if (any(head(2) == [11, 21, 22, 23, 24])) then     ! the beam's orientation line
                call line_integers(lex, extra, n, st)
                if (st%failed()) return
            end if
            got = 0
            do while (got < head(6))
                line = lex%line
                call line_integers(lex, labels(got + 1:), n, st)
                if (st%failed()) return
                if (n == 0) then
                    call set_error(st, STATUS_MESH_ERROR, 'element ' // to_text(head(1)) // &
                        ': ' // to_text(head(6) - got) // ' node label(s) missing', line=line)
                    return
                end if
                got = got + n
            end do
            do k = 1, head(6)
                nodes(k) = name_find(mesh%node_names, 'N' // to_text(labels(order(k))))
                if (nodes(k) == 0) then
                    call set_error(st, STATUS_MESH_ERROR, 'element ' // to_text(head(1)) // &
                        ': no node ' // to_text(labels(order(k))) // ' (dataset 2411 ' // &
                        'must come first)', line=line)
                    return
                end if
            end do
            call mesh_add_cell(mesh, 'M' // to_text(head(1)), ctype, nodes(1:head(6)), line, st)
            if (st%failed()) return
        end do
        call next_line(lex)
    end subroutine read_elements

    ! The cell type of an I-DEAS descriptor (0: not read) and the order of its node labels
    ! in Code_Aster's numbering of the cell.
    subroutine cell_kind(descriptor, ctype, order)
        integer(i4), intent(in) :: descriptor
        integer(i4), intent(out) :: ctype
        integer(i4), allocatable, intent(out) :: order(:)
        ctype = 0
        select case (descriptor)
        case (11, 21)
            ctype = CELL_SEG2
            order = [1, 2]
        case (22, 24)
            ctype = CELL_SEG3
            order = [1, 3, 2]
        case (41, 51, 61, 74, 81, 91)
            ctype = CELL_TRIA3
            order = [1, 2, 3]
        case (42, 52, 62, 72, 82, 92)
            ctype = CELL_TRIA6
            order = [1, 3, 5, 2, 4, 6]
        case (44, 54, 64, 71, 84, 94)
            ctype = CELL_QUAD4
            order = [1, 2, 3, 4]
        case (45, 55, 65, 75, 85, 95)
            ctype = CELL_QUAD8
            order = [1, 3, 5, 7, 2, 4, 6, 8]
        case (161)
            ctype = CELL_POI1
            order = [1]
        case default
            allocate (order(0))
        end select
    end subroutine cell_kind

    ! Datasets 2435, 2452, 2467, 2477: groups of nodes and elements.
    subroutine read_groups(lex, mesh, st)
        type(text_lexer_t), intent(inout) :: lex
        type(mesh_t), intent(inout) :: mesh
        type(status_t), intent(out) :: st
        integer(i4) :: head(16), entity(8), n, n_entities, k, got, line, first, last, index
        integer(i4), allocatable :: node_members(:), cell_members(:)
        integer(i4) :: n_nodes, n_cells
        character(len=:), allocatable :: name
        do while (.not. at_dataset_end(lex))
            line = lex%line
            call line_integers(lex, head, n, st)
            if (st%failed()) return
            if (n == 0) then
                call set_error(st, STATUS_MESH_ERROR, 'a group record starts with its ' // &
                    'numbers and entity count', line=line)
                return
            end if
            n_entities = head(n)
            if (n_entities < 0 .or. int(n_entities, i8) * 4_i8 > bytes_left(lex)) then
                call set_error(st, STATUS_MESH_ERROR, 'group of ' // to_text(n_entities) // &
                    ' entities: more than the file holds', line=line)
                return
            end if
            call next_token(lex, first, last)
            if (first == 0) then
                call set_error(st, STATUS_MESH_ERROR, 'a group without a name', &
                    line=lex%line)
                return
            end if
            name = trim(lex%text(first:last))
            call next_line(lex)
            allocate (node_members(n_entities), cell_members(n_entities))
            n_nodes = 0
            n_cells = 0
            got = 0
            do while (got < n_entities)
                line = lex%line
                call line_integers(lex, entity, n, st)
                if (st%failed()) return
                if (n == 0 .or. mod(n, 4) /= 0) then
                    call set_error(st, STATUS_MESH_ERROR, 'group ' // name // ': an entity ' // &
                        'is 4 integers (type, label, 0, 0)', line=line)
                    return
                end if
                do k = 1, n, 4
                    got = got + 1
                    if (got > n_entities) exit
                    select case (entity(k))
                    case (7)
                        index = name_find(mesh%node_names, 'N' // to_text(entity(k + 1)))
                        n_nodes = n_nodes + 1
                        node_members(n_nodes) = index
                    case (8)
                        index = name_find(mesh%cell_names, 'M' // to_text(entity(k + 1)))
                        n_cells = n_cells + 1
                        cell_members(n_cells) = index
                    case default
                        index = -1                    ! other entities: not kept
                    end select
                    if (index == 0) then
                        call set_error(st, STATUS_MESH_ERROR, 'group ' // name // ': no ' // &
                            trim(merge('node   ', 'element', entity(k) == 7)) // ' ' // &
                            to_text(entity(k + 1)), line=line)
                        return
                    end if
                end do
            end do
            if (n_nodes > 0) call mesh_add_node_group(mesh, name, node_members(1:n_nodes), &
                line, st)
            if (st%ok() .and. n_cells > 0) call mesh_add_cell_group(mesh, name, &
                cell_members(1:n_cells), line, st)
            if (st%failed()) return
            deallocate (node_members, cell_members)
        end do
        call next_line(lex)
    end subroutine read_groups

end module mesh_ideas_reader
