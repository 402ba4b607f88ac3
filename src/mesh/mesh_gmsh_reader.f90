!> Reader of Gmsh ASCII meshes, formats 2.2 and 4.1 (LIRE_MAILLAGE FORMAT='GMSH').
!>
!> Element types kept: 15 (point -> POI1), 1 (line -> SEG2), 2 (triangle -> TRIA3),
!> 3 (quadrangle -> QUAD4); any other type is an error naming it. Nodes are named N<tag>,
!> cells M<tag>. Each physical group becomes a GROUP_MA (its cells) and a GROUP_NO (the
!> nodes of those cells, in increasing node number) under its $PhysicalNames name, or
!> GM<tag> when it has none (Code_Aster's convention). Element 4.1 blocks take the physical
!> groups of their entity ($Entities); 2.2 elements take their first tag. An element tag
!> seen twice (2.2 writes an element once per physical group) adds the cell to the group
!> only. The mesh dimension is 2 when every z is 0, else 3. Sections other than
!> $MeshFormat, $PhysicalNames, $Entities, $Nodes, $Elements are skipped.
module mesh_gmsh_reader
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MESH_ERROR
    use strings, only: to_text
    use mesh_types, only: mesh_t, mesh_init, mesh_add_node, mesh_add_cell, &
        mesh_add_node_group, mesh_add_cell_group, mesh_finish, nodes_of_cells, &
        CELL_POI1, CELL_SEG2, CELL_TRIA3, CELL_QUAD4, CELL_TYPE_NODES
    use mesh_text_lexer, only: text_lexer_t, open_lexer, next_token, next_line, at_end, &
        parse_real, parse_integer
    implicit none
    private

    public :: read_gmsh_mesh

    !> What the reader collects besides the mesh itself.
    type :: gmsh_state_t
        integer(i4) :: version = 0                      !< 22 or 41
        integer(i4) :: n_phys = 0
        integer(i4), allocatable :: phys_dim(:), phys_tag(:)
        character(len=128), allocatable :: phys_name(:)
        integer(i4), allocatable :: tag_to_node(:), tag_to_cell(:)
        integer(i4) :: n_ent = 0                        !< 4.1 entities
        integer(i4), allocatable :: ent_dim(:), ent_tag(:), ent_phys(:, :)  !< (4, n) tags
        integer(i4), allocatable :: ent_lookup(:, :)    !< (0:3, tag) -> entity, 0 if none
        integer(i4) :: n_member = 0                     !< (physical index, cell) pairs
        integer(i4), allocatable :: member_phys(:), member_cell(:)
    end type gmsh_state_t

contains

    !> Reads the Gmsh ASCII file `path` (2.2 or 4.1) into `mesh`.
    !>  st : out, STATUS_IO_ERROR if unreadable; STATUS_MESH_ERROR with file and line for a
    !>       binary or unknown version, unsupported element type, unknown node tag, wrong
    !>       node count, bad number, duplicate node, degenerate cell, empty mesh.
    subroutine read_gmsh_mesh(path, mesh, st)
        character(len=*), intent(in) :: path
        type(mesh_t), intent(out) :: mesh
        type(status_t), intent(out) :: st
        type(text_lexer_t) :: lex
        type(gmsh_state_t) :: gs
        integer(i4) :: first, last
        call open_lexer(lex, path, st)
        if (st%failed()) return
        lex%percent_comments = .false.
        call mesh_init(mesh, 3_i4, path)
        allocate (gs%tag_to_node(1024), gs%tag_to_cell(1024), source=0_i4)
        allocate (gs%member_phys(1024), gs%member_cell(1024))
        allocate (gs%phys_dim(0), gs%phys_tag(0), gs%phys_name(0))
        allocate (gs%ent_dim(0), gs%ent_tag(0), gs%ent_phys(4, 0))
        do while (.not. at_end(lex))
            call next_token(lex, first, last)
            if (first == 0) then
                call next_line(lex)
                cycle
            end if
            select case (lex%text(first:last))
            case ('$MeshFormat')
                call read_format(lex, gs, mesh, st)
            case ('$PhysicalNames')
                call read_physical_names(lex, gs, st)
            case ('$Entities')
                call read_entities(lex, gs, st)
            case ('$Nodes')
                call read_nodes(lex, gs, mesh, st)
            case ('$Elements')
                call read_elements(lex, gs, mesh, st)
            case default
                call skip_section(lex, lex%text(first:last), mesh, st)
            end select
            if (st%failed()) then
                if (.not. allocated(st%file)) st%file = path
                if (st%line == 0) st%line = lex%line
                return
            end if
        end do
        if (gs%version == 0) then
            call set_error(st, STATUS_MESH_ERROR, 'no $MeshFormat section: not a Gmsh file', &
                           file=path, line=1)
            return
        end if
        mesh%dim = merge(2_i4, 3_i4, maxval(abs(mesh%coords(3, 1:mesh%n_nodes))) <= 0.0_dp)
        call make_groups(gs, mesh, lex%line, st)
        if (st%failed()) return
        call mesh_finish(mesh, lex%line, st)
    end subroutine read_gmsh_mesh

    ! Reads the next integer, across line ends unless same_line.
    subroutine get_int(lex, value, what, st, same_line)
        type(text_lexer_t), intent(inout) :: lex
        integer(i4), intent(out) :: value
        character(len=*), intent(in) :: what
        type(status_t), intent(inout) :: st
        logical, intent(in), optional :: same_line
        integer(i4) :: first, last
        logical :: ok
        value = 0
        call next_any(lex, first, last, present(same_line))
        if (first == 0) then
            call set_error(st, STATUS_MESH_ERROR, 'missing ' // what, line=lex%line)
            return
        end if
        call parse_integer(lex%text(first:last), value, ok)
        if (.not. ok) call set_error(st, STATUS_MESH_ERROR, what // ': "' // &
            lex%text(first:last) // '" is not an integer', line=lex%line)
    end subroutine get_int

    subroutine get_real(lex, value, what, st)
        type(text_lexer_t), intent(inout) :: lex
        real(dp), intent(out) :: value
        character(len=*), intent(in) :: what
        type(status_t), intent(inout) :: st
        integer(i4) :: first, last
        logical :: ok
        value = 0.0_dp
        call next_any(lex, first, last, .false.)
        if (first == 0) then
            call set_error(st, STATUS_MESH_ERROR, 'missing ' // what, line=lex%line)
            return
        end if
        call parse_real(lex%text(first:last), value, ok)
        if (.not. ok) call set_error(st, STATUS_MESH_ERROR, what // ': "' // &
            lex%text(first:last) // '" is not a real number', line=lex%line)
    end subroutine get_real

    subroutine next_any(lex, first, last, same_line)
        type(text_lexer_t), intent(inout) :: lex
        integer(i4), intent(out) :: first, last
        logical, intent(in) :: same_line
        do
            call next_token(lex, first, last)
            if (first > 0 .or. same_line .or. at_end(lex)) return
            call next_line(lex)
        end do
    end subroutine next_any

    ! Expects the token `word` (a section end) as the next token.
    subroutine expect(lex, word, st)
        type(text_lexer_t), intent(inout) :: lex
        character(len=*), intent(in) :: word
        type(status_t), intent(inout) :: st
        integer(i4) :: first, last
        call next_any(lex, first, last, .false.)
        if (first == 0) then
            call set_error(st, STATUS_MESH_ERROR, 'end of file: ' // word // ' is missing', &
                           line=lex%line)
        else if (lex%text(first:last) /= word) then
            call set_error(st, STATUS_MESH_ERROR, 'expected ' // word // ', found "' // &
                lex%text(first:last) // '" (wrong count in the section?)', line=lex%line)
        end if
    end subroutine expect

    subroutine read_format(lex, gs, mesh, st)
        type(text_lexer_t), intent(inout) :: lex
        type(gmsh_state_t), intent(inout) :: gs
        type(mesh_t), intent(in) :: mesh
        type(status_t), intent(inout) :: st
        integer(i4) :: first, last, file_type
        call next_any(lex, first, last, .false.)
        if (first == 0) then
            call set_error(st, STATUS_MESH_ERROR, 'missing Gmsh version', line=lex%line)
            return
        end if
        select case (lex%text(first:last))
        case ('2.2', '2.1', '2')
            gs%version = 22
        case ('4.1')
            gs%version = 41
        case default
            call set_error(st, STATUS_MESH_ERROR, 'Gmsh format version ' // &
                lex%text(first:last) // ' is not supported (2.2 or 4.1)', file=mesh%file, &
                line=lex%line)
            return
        end select
        call get_int(lex, file_type, 'file type', st)
        if (st%failed()) return
        if (file_type /= 0) then
            call set_error(st, STATUS_MESH_ERROR, 'binary Gmsh files are not supported ' // &
                '(save as ASCII)', line=lex%line)
            return
        end if
        call get_int(lex, file_type, 'data size', st)
        if (st%failed()) return
        call expect(lex, '$EndMeshFormat', st)
    end subroutine read_format

    subroutine read_physical_names(lex, gs, st)
        type(text_lexer_t), intent(inout) :: lex
        type(gmsh_state_t), intent(inout) :: gs
        type(status_t), intent(inout) :: st
        integer(i4) :: n, k, q1, q2, line_end
        call get_int(lex, n, 'number of physical names', st)
        if (st%failed()) return
        deallocate (gs%phys_dim, gs%phys_tag, gs%phys_name)
        allocate (gs%phys_dim(n), gs%phys_tag(n), gs%phys_name(n))
        gs%n_phys = n
        do k = 1, n
            call get_int(lex, gs%phys_dim(k), 'physical dimension', st)
            if (st%ok()) call get_int(lex, gs%phys_tag(k), 'physical tag', st, .true.)
            if (st%failed()) return
            line_end = index(lex%text(lex%pos:), achar(10)) + lex%pos - 2
            if (line_end < lex%pos) line_end = len(lex%text)
            q1 = index(lex%text(lex%pos:line_end), '"') + lex%pos - 1
            q2 = index(lex%text(lex%pos:line_end), '"', back=.true.) + lex%pos - 1
            if (q1 < lex%pos .or. q2 <= q1) then
                call set_error(st, STATUS_MESH_ERROR, 'physical name must be "quoted"', &
                               line=lex%line)
                return
            end if
            gs%phys_name(k) = lex%text(q1 + 1:q2 - 1)
            call next_line(lex)
        end do
        call expect(lex, '$EndPhysicalNames', st)
    end subroutine read_physical_names

    ! 4.1 $Entities: keeps, for each entity, its physical tags (up to 4).
    subroutine read_entities(lex, gs, st)
        type(text_lexer_t), intent(inout) :: lex
        type(gmsh_state_t), intent(inout) :: gs
        type(status_t), intent(inout) :: st
        integer(i4) :: counts(0:3), d, k, j, n_phys, n_bound, tag, e
        real(dp) :: x
        do d = 0, 3
            call get_int(lex, counts(d), 'entity count', st)
            if (st%failed()) return
        end do
        gs%n_ent = sum(counts)
        deallocate (gs%ent_dim, gs%ent_tag, gs%ent_phys)
        allocate (gs%ent_dim(gs%n_ent), gs%ent_tag(gs%n_ent), gs%ent_phys(4, gs%n_ent))
        gs%ent_phys = 0
        e = 0
        do d = 0, 3
            do k = 1, counts(d)
                e = e + 1
                gs%ent_dim(e) = d
                call get_int(lex, gs%ent_tag(e), 'entity tag', st)
                do j = 1, merge(3, 6, d == 0)
                    if (st%ok()) call get_real(lex, x, 'entity bounding box', st)
                end do
                if (st%ok()) call get_int(lex, n_phys, 'number of physical tags', st)
                do j = 1, n_phys
                    if (st%ok()) call get_int(lex, tag, 'physical tag', st)
                    if (j <= 4) gs%ent_phys(j, e) = abs(tag)
                end do
                if (d > 0) then
                    if (st%ok()) call get_int(lex, n_bound, 'number of bounding entities', st)
                    do j = 1, n_bound
                        if (st%ok()) call get_int(lex, tag, 'bounding entity', st)
                    end do
                end if
                if (st%failed()) return
            end do
        end do
        allocate (gs%ent_lookup(0:3, max(1_i4, maxval([1_i4, gs%ent_tag]))), source=0_i4)
        do e = 1, gs%n_ent
            if (gs%ent_tag(e) >= 1) gs%ent_lookup(gs%ent_dim(e), gs%ent_tag(e)) = e
        end do
        call expect(lex, '$EndEntities', st)
    end subroutine read_entities

    subroutine read_nodes(lex, gs, mesh, st)
        type(text_lexer_t), intent(inout) :: lex
        type(gmsh_state_t), intent(inout) :: gs
        type(mesh_t), intent(inout) :: mesh
        type(status_t), intent(inout) :: st
        integer(i4) :: n_blocks, n_total, b, k, dim, tag, parametric, n_in, i
        integer(i4), allocatable :: tags(:)
        real(dp) :: xyz(3), u
        if (gs%version == 41) then
            call get_int(lex, n_blocks, 'number of node blocks', st)
            if (st%ok()) call get_int(lex, n_total, 'number of nodes', st)
            if (st%ok()) call get_int(lex, tag, 'minimum node tag', st)
            if (st%ok()) call get_int(lex, tag, 'maximum node tag', st)
            if (st%failed()) return
            do b = 1, n_blocks
                call get_int(lex, dim, 'entity dimension', st)
                if (st%ok()) call get_int(lex, tag, 'entity tag', st)
                if (st%ok()) call get_int(lex, parametric, 'parametric flag', st)
                if (st%ok()) call get_int(lex, n_in, 'nodes in block', st)
                if (st%failed()) return
                allocate (tags(n_in))
                do k = 1, n_in
                    call get_int(lex, tags(k), 'node tag', st)
                    if (st%failed()) return
                end do
                do k = 1, n_in
                    do i = 1, 3
                        call get_real(lex, xyz(i), 'node coordinate', st)
                    end do
                    do i = 1, merge(dim, 0, parametric /= 0)
                        call get_real(lex, u, 'node parameter', st)
                    end do
                    if (st%failed()) return
                    call add_node(gs, mesh, tags(k), xyz, lex%line, st)
                    if (st%failed()) return
                end do
                deallocate (tags)
            end do
        else
            call get_int(lex, n_total, 'number of nodes', st)
            do k = 1, n_total
                if (st%ok()) call get_int(lex, tag, 'node tag', st)
                do i = 1, 3
                    if (st%ok()) call get_real(lex, xyz(i), 'node coordinate', st)
                end do
                if (st%ok()) call add_node(gs, mesh, tag, xyz, lex%line, st)
                if (st%failed()) return
            end do
        end if
        call expect(lex, '$EndNodes', st)
    end subroutine read_nodes

    subroutine add_node(gs, mesh, tag, xyz, line, st)
        type(gmsh_state_t), intent(inout) :: gs
        type(mesh_t), intent(inout) :: mesh
        integer(i4), intent(in) :: tag, line
        real(dp), intent(in) :: xyz(3)
        type(status_t), intent(inout) :: st
        if (tag < 1) then
            call set_error(st, STATUS_MESH_ERROR, 'node tag ' // to_text(tag) // &
                           ' must be positive', line=line)
            return
        end if
        call mesh_add_node(mesh, tag_name('N', tag), xyz, line, st)
        if (st%failed()) return
        call grow_map(gs%tag_to_node, tag)
        gs%tag_to_node(tag) = mesh%n_nodes
    end subroutine add_node

    ! prefix // decimal tag (tag >= 1), without an internal write (the reader names every
    ! node and cell: a formatted write per name would double the reading time).
    pure function tag_name(prefix, tag) result(name)
        character, intent(in) :: prefix
        integer(i4), intent(in) :: tag
        character(len=:), allocatable :: name
        character(len=11) :: digits
        integer(i4) :: value, k
        value = tag
        k = len(digits) + 1
        do
            k = k - 1
            digits(k:k) = achar(48 + mod(value, 10))
            value = value / 10
            if (value == 0) exit
        end do
        name = prefix // digits(k:)
    end function tag_name

    subroutine grow_map(map, tag)
        integer(i4), allocatable, intent(inout) :: map(:)
        integer(i4), intent(in) :: tag
        integer(i4), allocatable :: bigger(:)
        if (tag <= size(map)) return
        allocate (bigger(max(2 * size(map), tag)), source=0_i4)
        bigger(1:size(map)) = map
        call move_alloc(bigger, map)
    end subroutine grow_map

    subroutine read_elements(lex, gs, mesh, st)
        type(text_lexer_t), intent(inout) :: lex
        type(gmsh_state_t), intent(inout) :: gs
        type(mesh_t), intent(inout) :: mesh
        type(status_t), intent(inout) :: st
        integer(i4) :: n_blocks, n_total, b, k, dim, ent, etype, n_in, tag, n_tags, j, phys, e
        integer(i4) :: physicals(4)
        if (gs%version == 41) then
            call get_int(lex, n_blocks, 'number of element blocks', st)
            if (st%ok()) call get_int(lex, n_total, 'number of elements', st)
            if (st%ok()) call get_int(lex, tag, 'minimum element tag', st)
            if (st%ok()) call get_int(lex, tag, 'maximum element tag', st)
            if (st%failed()) return
            do b = 1, n_blocks
                call get_int(lex, dim, 'entity dimension', st)
                if (st%ok()) call get_int(lex, ent, 'entity tag', st)
                if (st%ok()) call get_int(lex, etype, 'element type', st)
                if (st%ok()) call get_int(lex, n_in, 'elements in block', st)
                if (st%failed()) return
                physicals = 0
                e = 0
                if (allocated(gs%ent_lookup) .and. dim >= 0 .and. dim <= 3 .and. ent >= 1) then
                    if (ent <= size(gs%ent_lookup, 2)) e = gs%ent_lookup(dim, ent)
                end if
                if (e > 0) physicals = gs%ent_phys(:, e)
                call next_line(lex)
                do k = 1, n_in
                    call get_int(lex, tag, 'element tag', st)
                    if (st%ok()) call add_element(lex, gs, mesh, tag, etype, physicals, st)
                    if (st%failed()) return
                end do
            end do
        else
            call get_int(lex, n_total, 'number of elements', st)
            call next_line(lex)
            do k = 1, n_total
                if (st%ok()) call get_int(lex, tag, 'element tag', st)
                if (st%ok()) call get_int(lex, etype, 'element type', st, .true.)
                if (st%ok()) call get_int(lex, n_tags, 'number of element tags', st, .true.)
                physicals = 0
                do j = 1, n_tags
                    if (st%ok()) call get_int(lex, phys, 'element tag list', st, .true.)
                    if (j == 1) physicals(1) = phys
                end do
                if (st%ok()) call add_element(lex, gs, mesh, tag, etype, physicals, st)
                if (st%failed()) return
            end do
        end if
        call expect(lex, '$EndElements', st)
    end subroutine read_elements

    ! Reads the node tags of one element to the end of its line and adds the cell.
    subroutine add_element(lex, gs, mesh, tag, etype, physicals, st)
        type(text_lexer_t), intent(inout) :: lex
        type(gmsh_state_t), intent(inout) :: gs
        type(mesh_t), intent(inout) :: mesh
        integer(i4), intent(in) :: tag, etype, physicals(4)
        type(status_t), intent(inout) :: st
        integer(i4) :: ctype, nodes(32), n, first, last, node_tag, j, line
        logical :: ok
        line = lex%line
        select case (etype)
        case (15); ctype = CELL_POI1
        case (1); ctype = CELL_SEG2
        case (2); ctype = CELL_TRIA3
        case (3); ctype = CELL_QUAD4
        case default
            call set_error(st, STATUS_MESH_ERROR, 'element ' // to_text(tag) // ': Gmsh ' // &
                'element type ' // to_text(etype) // ' is not supported (15 point POI1, ' // &
                '1 line SEG2, 2 triangle TRIA3, 3 quadrangle QUAD4)', line=line)
            return
        end select
        n = 0
        do
            call next_token(lex, first, last)
            if (first == 0 .or. n == size(nodes)) exit
            call parse_integer(lex%text(first:last), node_tag, ok)
            n = n + 1
            nodes(n) = 0
            if (ok .and. node_tag >= 1 .and. node_tag <= size(gs%tag_to_node)) &
                nodes(n) = gs%tag_to_node(node_tag)
            if (nodes(n) == 0) then
                call set_error(st, STATUS_MESH_ERROR, 'element ' // to_text(tag) // &
                    ': no node with tag ' // lex%text(first:last), line=line)
                return
            end if
        end do
        call next_line(lex)
        if (tag < 1) then
            call set_error(st, STATUS_MESH_ERROR, 'element tag must be positive', line=line)
            return
        end if
        call grow_map(gs%tag_to_cell, tag)
        if (gs%tag_to_cell(tag) == 0) then
            if (n /= CELL_TYPE_NODES(ctype)) then
                call set_error(st, STATUS_MESH_ERROR, 'element ' // to_text(tag) // ' has ' &
                    // to_text(n) // ' nodes, Gmsh type ' // to_text(etype) // ' has ' // &
                    to_text(CELL_TYPE_NODES(ctype)), line=line)
                return
            end if
            call mesh_add_cell(mesh, tag_name('M', tag), ctype, nodes(1:n), line, st)
            if (st%failed()) return
            gs%tag_to_cell(tag) = mesh%n_cells
        end if
        do j = 1, 4
            if (physicals(j) /= 0) call add_member(gs, physical_index(gs, physicals(j), &
                ctype), gs%tag_to_cell(tag))
        end do
    end subroutine add_element

    ! Index of physical group (dimension of ctype, tag) in gs%phys_*; unnamed ones are added
    ! as GM<tag>.
    integer(i4) function physical_index(gs, tag, ctype) result(k)
        type(gmsh_state_t), intent(inout) :: gs
        integer(i4), intent(in) :: tag, ctype
        integer(i4) :: dim
        dim = merge(0, merge(1, 2, ctype == CELL_SEG2), ctype == CELL_POI1)
        do k = 1, gs%n_phys
            if (gs%phys_tag(k) == tag .and. gs%phys_dim(k) == dim) return
        end do
        gs%phys_dim = [gs%phys_dim(1:gs%n_phys), dim]
        gs%phys_tag = [gs%phys_tag(1:gs%n_phys), tag]
        gs%phys_name = [character(len=128) :: gs%phys_name(1:gs%n_phys), 'GM' // to_text(tag)]
        gs%n_phys = gs%n_phys + 1
        k = gs%n_phys
    end function physical_index

    subroutine add_member(gs, phys, cell)
        type(gmsh_state_t), intent(inout) :: gs
        integer(i4), intent(in) :: phys, cell
        if (gs%n_member == size(gs%member_phys)) then
            gs%member_phys = [gs%member_phys, gs%member_phys]
            gs%member_cell = [gs%member_cell, gs%member_cell]
        end if
        gs%n_member = gs%n_member + 1
        gs%member_phys(gs%n_member) = phys
        gs%member_cell(gs%n_member) = cell
    end subroutine add_member

    ! One GROUP_MA and one GROUP_NO per physical group that has cells, in $PhysicalNames
    ! order.
    subroutine make_groups(gs, mesh, line, st)
        type(gmsh_state_t), intent(in) :: gs
        type(mesh_t), intent(inout) :: mesh
        integer(i4), intent(in) :: line
        type(status_t), intent(inout) :: st
        integer(i4) :: k
        integer(i4), allocatable :: cells(:)
        do k = 1, gs%n_phys
            cells = pack(gs%member_cell(1:gs%n_member), gs%member_phys(1:gs%n_member) == k)
            if (size(cells) == 0) cycle
            call mesh_add_cell_group(mesh, trim(gs%phys_name(k)), cells, line, st)
            if (st%ok()) call mesh_add_node_group(mesh, trim(gs%phys_name(k)), &
                                                  nodes_of_cells(mesh, cells), line, st)
            if (st%failed()) return
        end do
    end subroutine make_groups

    ! Skips an unknown section `$Name` up to `$EndName`.
    subroutine skip_section(lex, header, mesh, st)
        type(text_lexer_t), intent(inout) :: lex
        character(len=*), intent(in) :: header
        type(mesh_t), intent(in) :: mesh
        type(status_t), intent(inout) :: st
        integer(i4) :: first, last, start_line
        character(len=:), allocatable :: closing
        start_line = lex%line
        if (header(1:1) /= '$') then
            call set_error(st, STATUS_MESH_ERROR, 'unexpected "' // header // &
                '" outside a $Section', file=mesh%file, line=lex%line)
            return
        end if
        closing = '$End' // header(2:)
        do while (.not. at_end(lex))
            call next_line(lex)
            call next_token(lex, first, last)
            if (first > 0) then
                if (lex%text(first:last) == closing) then
                    call next_line(lex)
                    return
                end if
            end if
        end do
        call set_error(st, STATUS_MESH_ERROR, 'section ' // header // ' has no ' // closing, &
                       file=mesh%file, line=start_line)
    end subroutine skip_section

end module mesh_gmsh_reader
