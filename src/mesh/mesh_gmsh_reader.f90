!> Reader of Gmsh ASCII meshes, formats 2.2 and 4.1 (LIRE_MAILLAGE FORMAT='GMSH'), and 1.0
!> as the 2.2 text it amounts to (mesh_gmsh1_text).
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
!>
!> Nothing read from the file is taken on trust (issue 13): every count is checked against
!> the bytes left in the file before anything is allocated, the 4.1 header totals ($Nodes
!> and $Elements: number of entities, tags, smallest and largest tag) against the blocks
!> actually read, each section may appear once, and tags of any size are looked up through
!> the names (a dense tag array caches the usual numbering 1..n, its size bounded by the
!> entities read).
module mesh_gmsh_reader
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MESH_ERROR
    use strings, only: to_text
    use mesh_name_index, only: name_index_t, name_add, name_find
    use mesh_types, only: mesh_t, mesh_init, mesh_add_node, mesh_add_cell, &
        mesh_add_node_group, mesh_add_cell_group, mesh_finish, nodes_of_cells, &
        CELL_POI1, CELL_SEG2, CELL_TRIA3, CELL_QUAD4, CELL_SEG3, CELL_TRIA6, CELL_QUAD8, &
        CELL_QUAD9, CELL_TYPE_NODES, CELL_TYPE_DIM
    use mesh_gmsh1_text, only: is_gmsh1, gmsh1_to_gmsh22, GMSH1_HEADER_LINES
    use mesh_gmsh_tokens, only: get_int, get_count, check_count, get_real, next_any, expect
    use mesh_text_lexer, only: text_lexer_t, open_lexer, next_token, next_line, at_end, &
        parse_integer, bytes_left
    implicit none
    private

    public :: read_gmsh_mesh

    !> Fewest bytes one item of a section takes in a valid file (tokens and separators): a
    !> count that needs more bytes than are left in the file is refused before allocating.
    integer(i8), parameter :: BYTES_PHYSICAL_NAME = 7   !< `0 1 ""` and a line end
    integer(i8), parameter :: BYTES_ENTITY = 10         !< `1 0 0 0 0` (a point)
    integer(i8), parameter :: BYTES_BLOCK = 8           !< `0 1 0 1` (4.1 block header)
    integer(i8), parameter :: BYTES_NODE = 8            !< `1 0 0 0` / `1`, `0 0 0` (4.1)
    integer(i8), parameter :: BYTES_ELEMENT = 4         !< `1 1` (4.1), `1 15 0 1` (2.2)
    integer(i8), parameter :: BYTES_TAG = 2             !< one integer and a separator
    !> Sections read (others are skipped), for the duplicate-section check.
    character(len=*), parameter :: SECTIONS(5) = [character(len=16) :: '$MeshFormat', &
        '$PhysicalNames', '$Entities', '$Nodes', '$Elements']

    !> What the reader collects besides the mesh itself.
    type :: gmsh_state_t
        integer(i4) :: version = 0                      !< 22 or 41
        integer(i4) :: section_line(5) = 0              !< line of each section in SECTIONS
        integer(i4) :: n_phys = 0
        integer(i4), allocatable :: phys_dim(:), phys_tag(:)
        character(len=128), allocatable :: phys_name(:)
        type(name_index_t) :: phys_keys                 !< 'dim:tag' -> index in phys_*
        integer(i4), allocatable :: tag_to_node(:), tag_to_cell(:)   !< caches, 0 = unknown
        integer(i4) :: n_ent = 0                        !< 4.1 entities
        integer(i8), allocatable :: ent_key(:)          !< dim * 2**32 + tag, sorted
        integer(i4), allocatable :: ent_phys(:, :)      !< (4, n) physical tags, same order
        integer(i4) :: n_member = 0                     !< (physical index, cell) pairs
        integer(i4), allocatable :: member_phys(:), member_cell(:)
    end type gmsh_state_t

contains

    !> Reads the Gmsh ASCII file `path` (2.2 or 4.1) into `mesh`.
    !>  st : out, STATUS_IO_ERROR if unreadable; STATUS_MESH_ERROR with file and line for a
    !>       binary or unknown version, unsupported element type, unknown node tag, wrong
    !>       node count, bad number, duplicate node, degenerate cell, empty mesh, a count
    !>       that is negative or more than the file can hold, header totals that disagree
    !>       with the data, a section given twice.
    subroutine read_gmsh_mesh(path, mesh, st)
        character(len=*), intent(in) :: path
        type(mesh_t), intent(out) :: mesh
        type(status_t), intent(out) :: st
        type(text_lexer_t) :: lex
        type(gmsh_state_t) :: gs
        integer(i4) :: first, last, k
        character(len=:), allocatable :: converted
        call open_lexer(lex, path, st)
        if (st%failed()) return
        if (is_gmsh1(lex%text)) then   ! format 1.0: read as the 2.2 text it amounts to
            call gmsh1_to_gmsh22(lex%text, path, converted, st)
            if (st%failed()) return
            call move_alloc(converted, lex%text)
            lex%line = 1 - GMSH1_HEADER_LINES
        end if
        lex%percent_comments = .false.
        call mesh_init(mesh, 3_i4, path)
        allocate (gs%tag_to_node(1024), gs%tag_to_cell(1024), source=0_i4)
        allocate (gs%member_phys(1024), gs%member_cell(1024))
        allocate (gs%phys_dim(0), gs%phys_tag(0), gs%phys_name(0))
        allocate (gs%ent_key(0), gs%ent_phys(4, 0))
        do while (.not. at_end(lex))
            call next_token(lex, first, last)
            if (first == 0) then
                call next_line(lex)
                cycle
            end if
            k = section_index(lex%text(first:last))
            if (k > 0) then
                if (gs%section_line(k) > 0) then
                    call set_error(st, STATUS_MESH_ERROR, 'a second ' // trim(SECTIONS(k)) // &
                        ' section (the first is at line ' // to_text(gs%section_line(k)) // &
                        '): a Gmsh file has one', file=path, line=lex%line)
                    return
                end if
                gs%section_line(k) = lex%line
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
        if (mesh%n_nodes > 0) mesh%dim = merge(2_i4, 3_i4, &
            maxval(abs(mesh%coords(3, 1:mesh%n_nodes))) <= 0.0_dp)
        call make_groups(gs, mesh, lex%line, st)
        if (st%failed()) return
        call mesh_finish(mesh, lex%line, st)
    end subroutine read_gmsh_mesh

    ! Index of a section header in SECTIONS, 0 for another token.
    pure integer function section_index(word) result(k)
        character(len=*), intent(in) :: word
        do k = 1, size(SECTIONS)
            if (trim(SECTIONS(k)) == word) return
        end do
        k = 0
    end function section_index


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
        integer(i4) :: n, k, q1, q2, line_end, slot
        call get_count(lex, n, 'number of physical names', BYTES_PHYSICAL_NAME, st)
        if (st%failed()) return
        deallocate (gs%phys_dim, gs%phys_tag, gs%phys_name)
        allocate (gs%phys_dim(n), gs%phys_tag(n), gs%phys_name(n))
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
            call name_add(gs%phys_keys, physical_key(gs%phys_dim(k), gs%phys_tag(k)), slot)
            if (slot < 0) then
                call set_error(st, STATUS_MESH_ERROR, 'physical group ' // &
                    to_text(gs%phys_tag(k)) // ' of dimension ' // to_text(gs%phys_dim(k)) // &
                    ' is named twice', line=lex%line)
                return
            end if
            gs%n_phys = k
            call next_line(lex)
        end do
        call expect(lex, '$EndPhysicalNames', st)
    end subroutine read_physical_names

    ! 'dim:tag', the key of a physical group.
    pure function physical_key(dim, tag) result(key)
        integer(i4), intent(in) :: dim, tag
        character(len=:), allocatable :: key
        key = tag_name(' ', abs(dim)) // ':' // tag_name(merge('-', ' ', tag < 0), abs(tag))
    end function physical_key

    ! 4.1 $Entities: keeps, for each entity, its physical tags (up to 4), sorted by
    ! (dimension, tag) for the element blocks' look-up.
    subroutine read_entities(lex, gs, st)
        type(text_lexer_t), intent(inout) :: lex
        type(gmsh_state_t), intent(inout) :: gs
        type(status_t), intent(inout) :: st
        integer(i4) :: counts(0:3), d, k, j, n_phys, n_bound, tag, e
        integer(i4), allocatable :: order(:)
        real(dp) :: x
        do d = 0, 3
            call get_count(lex, counts(d), 'number of entities of dimension ' // to_text(d), &
                           BYTES_ENTITY, st)
            if (st%failed()) return
        end do
        if (sum(int(counts, i8)) > bytes_left(lex) / BYTES_ENTITY) then
            call set_error(st, STATUS_MESH_ERROR, to_text(sum(int(counts, i8))) // &
                ' entities are more than the bytes left in the file can hold', line=lex%line)
            return
        end if
        gs%n_ent = sum(counts)
        deallocate (gs%ent_key, gs%ent_phys)
        allocate (gs%ent_key(gs%n_ent), gs%ent_phys(4, gs%n_ent))
        gs%ent_phys = 0
        e = 0
        do d = 0, 3
            do k = 1, counts(d)
                e = e + 1
                call get_int(lex, tag, 'entity tag', st)
                gs%ent_key(e) = entity_key(d, tag)
                do j = 1, merge(3, 6, d == 0)
                    if (st%ok()) call get_real(lex, x, 'entity bounding box', st)
                end do
                if (st%ok()) call get_count(lex, n_phys, 'number of physical tags', &
                                            BYTES_TAG, st)
                do j = 1, n_phys
                    if (st%failed()) exit
                    call get_int(lex, tag, 'physical tag', st)
                    if (j <= 4) gs%ent_phys(j, e) = tag
                end do
                if (d > 0) then
                    if (st%ok()) call get_count(lex, n_bound, 'number of bounding entities', &
                                                BYTES_TAG, st)
                    do j = 1, n_bound
                        if (st%failed()) exit
                        call get_int(lex, tag, 'bounding entity', st)
                    end do
                end if
                if (st%failed()) return
            end do
        end do
        order = sort_order(gs%ent_key)
        gs%ent_key = gs%ent_key(order)
        gs%ent_phys = gs%ent_phys(:, order)
        do e = 2, gs%n_ent
            if (gs%ent_key(e) == gs%ent_key(e - 1)) then
                call set_error(st, STATUS_MESH_ERROR, 'entity ' // &
                    to_text(int(iand(gs%ent_key(e), int(z'FFFFFFFF', i8)) - 2_i8**31, i4)) // &
                    ' of dimension ' // to_text(gs%ent_key(e) / 2_i8**32) // &
                    ' is defined twice', line=lex%line)
                return
            end if
        end do
        call expect(lex, '$EndEntities', st)
    end subroutine read_entities

    ! (dimension, tag) as one sortable key.
    pure integer(i8) function entity_key(dim, tag)
        integer(i4), intent(in) :: dim, tag
        entity_key = int(dim, i8) * 2_i8**32 + (int(tag, i8) + 2_i8**31)
    end function entity_key

    ! Index of entity (dim, tag) in gs%ent_key (binary search), 0 if none.
    integer(i4) function find_entity(gs, dim, tag) result(e)
        type(gmsh_state_t), intent(in) :: gs
        integer(i4), intent(in) :: dim, tag
        integer(i4) :: lo, hi, mid
        integer(i8) :: key
        e = 0
        if (dim < 0 .or. dim > 3) return
        key = entity_key(dim, tag)
        lo = 1
        hi = gs%n_ent
        do while (lo <= hi)
            mid = lo + (hi - lo) / 2
            if (gs%ent_key(mid) == key) then
                e = mid
                return
            else if (gs%ent_key(mid) < key) then
                lo = mid + 1
            else
                hi = mid - 1
            end if
        end do
    end function find_entity

    ! Permutation sorting `keys` increasingly (merge sort, stable).
    function sort_order(keys) result(order)
        integer(i8), intent(in) :: keys(:)
        integer(i4), allocatable :: order(:)
        integer(i4), allocatable :: work(:)
        integer(i4) :: n, width, lo, mid, hi, i, j, k
        n = size(keys, kind=i4)
        order = [(i, i = 1, n)]
        allocate (work(n))
        width = 1
        do while (width < n)
            lo = 1
            do while (lo <= n)
                mid = min(lo + width - 1, n)
                hi = min(lo + 2 * width - 1, n)
                i = lo
                j = mid + 1
                do k = lo, hi
                    if (j > hi) then
                        work(k) = order(i); i = i + 1
                    else if (i > mid) then
                        work(k) = order(j); j = j + 1
                    else if (keys(order(j)) < keys(order(i))) then
                        work(k) = order(j); j = j + 1
                    else
                        work(k) = order(i); i = i + 1
                    end if
                end do
                lo = lo + 2 * width
            end do
            order = work
            if (width > n / 2) exit
            width = 2 * width
        end do
    end function sort_order

    subroutine read_nodes(lex, gs, mesh, st)
        type(text_lexer_t), intent(inout) :: lex
        type(gmsh_state_t), intent(inout) :: gs
        type(mesh_t), intent(inout) :: mesh
        type(status_t), intent(inout) :: st
        integer(i4) :: n_blocks, n_total, b, k, dim, tag, parametric, n_in, i, min_tag, &
            max_tag, lowest, highest, header_line
        integer(i8) :: n_read
        integer(i4), allocatable :: tags(:)
        real(dp) :: xyz(3), u
        if (gs%version == 41) then
            call get_count(lex, n_blocks, 'number of node blocks', BYTES_BLOCK, st)
            header_line = lex%line
            if (st%ok()) call get_count(lex, n_total, 'number of nodes', BYTES_NODE, st)
            if (st%ok()) call get_int(lex, min_tag, 'minimum node tag', st)
            if (st%ok()) call get_int(lex, max_tag, 'maximum node tag', st)
            if (st%failed()) return
            n_read = 0
            lowest = huge(1_i4)
            highest = -huge(1_i4)
            do b = 1, n_blocks
                call get_int(lex, dim, 'entity dimension', st)
                if (st%ok()) call get_int(lex, tag, 'entity tag', st)
                if (st%ok()) call get_int(lex, parametric, 'parametric flag', st)
                if (st%ok()) call get_count(lex, n_in, 'nodes in block', BYTES_NODE, st)
                if (st%failed()) return
                if (dim < 0 .or. dim > 3 .or. parametric < 0 .or. parametric > 1) then
                    call set_error(st, STATUS_MESH_ERROR, 'node block ' // to_text(b) // &
                        ': entity dimension ' // to_text(dim) // ' and parametric flag ' // &
                        to_text(parametric) // ' (expected 0 to 3, and 0 or 1)', line=lex%line)
                    return
                end if
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
                    lowest = min(lowest, tags(k))
                    highest = max(highest, tags(k))
                end do
                n_read = n_read + n_in
                deallocate (tags)
            end do
            call check_totals('$Nodes', 'nodes', header_line, n_total, n_read, min_tag, &
                              max_tag, lowest, highest, st)
            if (st%failed()) return
        else
            call get_count(lex, n_total, 'number of nodes', BYTES_NODE, st)
            do k = 1, n_total
                if (st%ok()) call get_int(lex, tag, 'node tag', st)
                do i = 1, 3
                    if (st%ok()) call get_real(lex, xyz(i), 'node coordinate', st)
                end do
                if (st%ok()) call add_node(gs, mesh, tag, xyz, lex%line, st)
                if (st%failed()) return
            end do
            if (st%failed()) return
        end if
        call expect(lex, '$EndNodes', st)
    end subroutine read_nodes

    ! A 4.1 section header (number of entities, smallest and largest tag) against what the
    ! blocks held (Gmsh 2.2 counts are checked by the section end that follows them).
    subroutine check_totals(section, what, line, n_total, n_read, min_tag, max_tag, lowest, &
                            highest, st)
        character(len=*), intent(in) :: section, what
        integer(i4), intent(in) :: line, n_total, min_tag, max_tag, lowest, highest
        integer(i8), intent(in) :: n_read
        type(status_t), intent(inout) :: st
        if (n_read /= int(n_total, i8)) then
            call set_error(st, STATUS_MESH_ERROR, 'the ' // section // ' header says ' // &
                to_text(n_total) // ' ' // what // ', its blocks hold ' // to_text(n_read), &
                line=line)
        else if (n_read > 0 .and. (min_tag /= lowest .or. max_tag /= highest)) then
            call set_error(st, STATUS_MESH_ERROR, 'the ' // section // ' header says tags ' // &
                to_text(min_tag) // ' to ' // to_text(max_tag) // ', its blocks hold tags ' // &
                to_text(lowest) // ' to ' // to_text(highest), line=line)
        end if
    end subroutine check_totals

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
        call cache_tag(gs%tag_to_node, tag, mesh%n_nodes)
    end subroutine add_node

    ! Node number of node tag `tag`, 0 if there is none.
    integer(i4) function node_of_tag(gs, mesh, tag) result(node)
        type(gmsh_state_t), intent(in) :: gs
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: tag
        node = 0
        if (tag < 1) return
        if (tag <= size(gs%tag_to_node)) node = gs%tag_to_node(tag)
        if (node == 0) node = name_find(mesh%node_names, tag_name('N', tag))
    end function node_of_tag

    ! Cell number of element tag `tag`, 0 if none.
    integer(i4) function cell_of_tag(gs, mesh, tag) result(cell)
        type(gmsh_state_t), intent(in) :: gs
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: tag
        cell = 0
        if (tag <= size(gs%tag_to_cell)) cell = gs%tag_to_cell(tag)
        if (cell == 0) cell = name_find(mesh%cell_names, tag_name('M', tag))
    end function cell_of_tag

    ! prefix // decimal tag (tag >= 0), without an internal write (the reader names every
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
        name = trim(prefix) // digits(k:)
    end function tag_name

    ! Records tag -> number in a dense cache when the tag is small enough: at most twice the
    ! number of entities read so far plus 1024, so a file with huge or sparse tags costs no
    ! memory beyond its entities (those are then found through their names).
    subroutine cache_tag(map, tag, number)
        integer(i4), allocatable, intent(inout) :: map(:)
        integer(i4), intent(in) :: tag, number
        integer(i4), allocatable :: bigger(:)
        if (tag < 1 .or. int(tag, i8) > 2_i8 * number + 1024_i8) return
        if (tag > size(map)) then
            allocate (bigger(int(min(2_i8 * size(map, kind=i8), 2_i8 * number + 1024_i8, &
                                     int(huge(1_i4), i8)), i4)), source=0_i4)
            bigger(1:size(map)) = map
            call move_alloc(bigger, map)
            if (tag > size(map)) return
        end if
        map(tag) = number
    end subroutine cache_tag

    subroutine read_elements(lex, gs, mesh, st)
        type(text_lexer_t), intent(inout) :: lex
        type(gmsh_state_t), intent(inout) :: gs
        type(mesh_t), intent(inout) :: mesh
        type(status_t), intent(inout) :: st
        integer(i4) :: n_blocks, n_total, b, k, dim, ent, etype, n_in, tag, n_tags, j, phys, e
        integer(i4) :: physicals(4), min_tag, max_tag, lowest, highest, header_line
        integer(i8) :: n_read
        if (gs%version == 41) then
            call get_count(lex, n_blocks, 'number of element blocks', BYTES_BLOCK, st)
            header_line = lex%line
            if (st%ok()) call get_count(lex, n_total, 'number of elements', BYTES_ELEMENT, st)
            if (st%ok()) call get_int(lex, min_tag, 'minimum element tag', st)
            if (st%ok()) call get_int(lex, max_tag, 'maximum element tag', st)
            if (st%failed()) return
            n_read = 0
            lowest = huge(1_i4)
            highest = -huge(1_i4)
            do b = 1, n_blocks
                call get_int(lex, dim, 'entity dimension', st)
                if (st%ok()) call get_int(lex, ent, 'entity tag', st)
                if (st%ok()) call get_int(lex, etype, 'element type', st)
                if (st%ok()) call get_count(lex, n_in, 'elements in block', BYTES_ELEMENT, st)
                if (st%failed()) return
                physicals = 0
                e = find_entity(gs, dim, ent)
                if (e > 0) physicals = gs%ent_phys(:, e)
                call next_line(lex)
                do k = 1, n_in
                    call get_int(lex, tag, 'element tag', st)
                    if (st%ok()) call add_element(lex, gs, mesh, tag, etype, physicals, st)
                    if (st%failed()) return
                    lowest = min(lowest, tag)
                    highest = max(highest, tag)
                end do
                n_read = n_read + n_in
            end do
            call check_totals('$Elements', 'elements', header_line, n_total, n_read, min_tag, &
                              max_tag, lowest, highest, st)
            if (st%failed()) return
        else
            call get_count(lex, n_total, 'number of elements', BYTES_ELEMENT, st)
            if (st%failed()) return
            call next_line(lex)
            do k = 1, n_total
                call get_int(lex, tag, 'element tag', st)
                if (st%ok()) call get_int(lex, etype, 'element type', st, .true.)
                if (st%ok()) call get_count(lex, n_tags, 'number of element tags', BYTES_TAG, &
                                            st, .true.)
                physicals = 0
                do j = 1, n_tags
                    if (st%failed()) exit
                    call get_int(lex, phys, 'element tag list', st, .true.)
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
        integer(i4) :: ctype, nodes(32), n, first, last, node_tag, j, line, cell
        logical :: ok
        line = lex%line
        select case (etype)
        case (15); ctype = CELL_POI1
        case (1); ctype = CELL_SEG2
        case (2); ctype = CELL_TRIA3
        case (3); ctype = CELL_QUAD4
        case (8); ctype = CELL_SEG3          ! Gmsh's node orders are Code_Aster's for these
        case (9); ctype = CELL_TRIA6
        case (16); ctype = CELL_QUAD8
        case (10); ctype = CELL_QUAD9
        case default
            call set_error(st, STATUS_MESH_ERROR, 'element ' // to_text(tag) // ': Gmsh ' // &
                'element type ' // to_text(etype) // ' is not supported (15 point POI1, ' // &
                '1 line SEG2, 8 line SEG3, 2 triangle TRIA3, 9 triangle TRIA6, 3 ' // &
                'quadrangle QUAD4, 16 quadrangle QUAD8, 10 quadrangle QUAD9)', line=line)
            return
        end select
        if (tag < 1) then
            call set_error(st, STATUS_MESH_ERROR, 'element tag ' // to_text(tag) // &
                ' must be positive', line=line)
            return
        end if
        n = 0
        do
            call next_token(lex, first, last)
            if (first == 0 .or. n == size(nodes)) exit
            call parse_integer(lex%text(first:last), node_tag, ok)
            n = n + 1
            nodes(n) = 0
            if (ok) nodes(n) = node_of_tag(gs, mesh, node_tag)
            if (nodes(n) == 0) then
                call set_error(st, STATUS_MESH_ERROR, 'element ' // to_text(tag) // &
                    ': no node with tag ' // lex%text(first:last), line=line)
                return
            end if
        end do
        call next_line(lex)
        cell = cell_of_tag(gs, mesh, tag)
        if (cell == 0) then
            if (n /= CELL_TYPE_NODES(ctype)) then
                call set_error(st, STATUS_MESH_ERROR, 'element ' // to_text(tag) // ' has ' &
                    // to_text(n) // ' nodes, Gmsh type ' // to_text(etype) // ' has ' // &
                    to_text(CELL_TYPE_NODES(ctype)), line=line)
                return
            end if
            call mesh_add_cell(mesh, tag_name('M', tag), ctype, nodes(1:n), line, st)
            if (st%failed()) return
            cell = mesh%n_cells
            call cache_tag(gs%tag_to_cell, tag, cell)
        else if (gs%version == 41) then
            call set_error(st, STATUS_MESH_ERROR, 'element tag ' // to_text(tag) // &
                ' is used twice', line=line)
            return
        end if
        do j = 1, 4
            if (physicals(j) /= 0) call add_member(gs, physical_index(gs, physicals(j), &
                ctype), cell)
        end do
    end subroutine add_element

    ! Index of physical group (dimension of ctype, tag) in gs%phys_*; unnamed ones are added
    ! as GM<tag>. A physical tag is positive; Gmsh writes a negative one for an entity whose
    ! orientation is reversed, which names the same group.
    integer(i4) function physical_index(gs, tag, ctype) result(k)
        type(gmsh_state_t), intent(inout) :: gs
        integer(i4), intent(in) :: tag, ctype
        integer(i4) :: dim, t
        dim = CELL_TYPE_DIM(ctype)
        t = abs(tag)
        if (t < 0) t = huge(1_i4)      ! abs(-2**31) stays negative
        k = name_find(gs%phys_keys, physical_key(dim, t))
        if (k > 0) return
        call name_add(gs%phys_keys, physical_key(dim, t), k)
        gs%phys_dim = [gs%phys_dim(1:gs%n_phys), dim]
        gs%phys_tag = [gs%phys_tag(1:gs%n_phys), t]
        gs%phys_name = [character(len=128) :: gs%phys_name(1:gs%n_phys), 'GM' // to_text(t)]
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
    ! order; members bucketed by group first (one pass, whatever the number of groups).
    subroutine make_groups(gs, mesh, line, st)
        type(gmsh_state_t), intent(in) :: gs
        type(mesh_t), intent(inout) :: mesh
        integer(i4), intent(in) :: line
        type(status_t), intent(inout) :: st
        integer(i4) :: k, m
        integer(i4), allocatable :: ptr(:), fill(:), cells(:)
        allocate (ptr(gs%n_phys + 1), source=0_i4)
        do m = 1, gs%n_member
            ptr(gs%member_phys(m) + 1) = ptr(gs%member_phys(m) + 1) + 1
        end do
        ptr(1) = 1
        do k = 1, gs%n_phys
            ptr(k + 1) = ptr(k + 1) + ptr(k)
        end do
        allocate (cells(gs%n_member))
        fill = ptr(1:gs%n_phys)
        do m = 1, gs%n_member
            cells(fill(gs%member_phys(m))) = gs%member_cell(m)
            fill(gs%member_phys(m)) = fill(gs%member_phys(m)) + 1
        end do
        do k = 1, gs%n_phys
            if (ptr(k + 1) == ptr(k)) cycle
            associate (group => cells(ptr(k):ptr(k + 1) - 1))
                call mesh_add_cell_group(mesh, trim(gs%phys_name(k)), group, line, st)
                if (st%ok()) call mesh_add_node_group(mesh, trim(gs%phys_name(k)), &
                                                      nodes_of_cells(mesh, group), line, st)
            end associate
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
