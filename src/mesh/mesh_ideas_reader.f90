!> I-DEAS universal files (LIRE_MAILLAGE FORMAT='IDEAS'), converted as Code_Aster's PRE_IDEAS
!> converts them (op0047: presup reads the datasets, ecrneu, ecrelt and slegro write the
!> .mail), so that nodes, cells and groups have Code_Aster's names and orders.
!>
!> The file is a sequence of datasets, each between two lines `    -1`, its number on the
!> first line. Read (Code_Aster's formats, fixed columns):
!>   2411, 781  nodes: (4I10) label, export and displacement coordinate systems, colour, then
!>              (3D25.16) x y z;  15: (4I10, 3E13.6) on one line
!>   2412       cells: (6I10) label, FE descriptor, physical and material properties, colour,
!>              node count; beams (descriptors 11, 21-24) one more line (orientation, not
!>              read); then the node labels (8I10);  780: (8I10) label, descriptor, 4
!>              property numbers, colour, node count, then as 2412
!>   2435, 2452, 2467, 2477  groups: (I10, 60X, I10) number and entity count, the name (A20),
!>              then (2(I10, I10, 20X)) entity type and label, 2 a line;  752 (I10, 40X, I10),
!>              2417 (I10, 50X, I10), 2429, 2430, 2432 (I10, 60X, I10): then 4 a line (8I10)
!>   2420, 18   coordinate systems: their types (a node given in a cylindrical or spherical
!>              one is refused, STBTRIAS_10: Code_Aster does not convert them)
!> Other datasets (151 header, 164 units, ...) are skipped, noted.
!>
!> The .mail written: nodes N<label> in the file's order (COOR_3D, coordinates as given:
!> Code_Aster applies no coordinate system); cells M<label> grouped by kind in Code_Aster's
!> order (cov4v5, ecrelt: SEG2, TRIA3, TRIA6, QUAD4, QUAD8, then the discrete SEG2 and POI1
!> of springs, masses and rigid links, then SEG3), in the file's order within a kind, with
!> quadratic cells' nodes corners first (inistb); groups under the first 8 characters of
!> their names, cut at the first character that cannot continue a name (STBTRIAS_5, _7), a
!> group whose name is no name skipped (STBTRIAS_6), `PERMANENT...` named GRNO<n> / GRMA<n>,
!> the cells of a `COUL_...` group not written (STBTRIAS_8), entities other than nodes (7)
!> and cells (8) ignored, empty groups not written. CREA_GROUP_COUL='OUI' adds a GROUP_NO
!> and a GROUP_MA COUL_<c> per colour c (0-255) of the nodes and cells.
module mesh_ideas_reader
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MESH_ERROR
    use strings, only: string_t, to_text
    use text_file, only: read_text_file, split_text_lines
    use mesh_types, only: mesh_t
    use mesh_aster_reader, only: read_aster_text
    use mesh_text_lexer, only: parse_real, parse_integer
    use mesh_ideas_tables, only: cell_kind, kind_order, N_KINDS, KIND_NAMES, KIND_NODES, &
        KIND_PARASOL, BEAM_DESCRIPTORS
    use mesh_gibi_writer, only: join_lines
    implicit none
    private

    public :: ideas_to_aster, read_ideas_mesh

    integer(i4), parameter :: MAX_COLOUR = 255

    !> Lines of the file, the last one read, and the .mail lines written (with the line of
    !> the file each comes from).
    type :: work_t
        type(string_t), allocatable :: lines(:)
        integer(i4) :: k = 0
        character(len=:), allocatable :: path
        type(string_t), allocatable :: out(:)
        integer(i4), allocatable :: origin(:)
        integer(i4) :: n_out = 0
        integer(i4) :: here = 1
        integer(i4), allocatable :: system_label(:), system_type(:)
        integer(i4) :: last_system = -1
        logical :: colours = .false., has_nodes = .false.
    end type work_t

contains

    !> LIRE_MAILLAGE(FORMAT='IDEAS'): the mesh PRE_IDEAS would write, read as a .mail.
    !>  colour_groups : CREA_GROUP_COUL='OUI'
    !>  notes         : out, lines for the .mess (datasets skipped, names cut)
    !>  st            : STATUS_MESH_ERROR at the universal file's line
    subroutine read_ideas_mesh(path, colour_groups, mesh, st, notes)
        character(len=*), intent(in) :: path
        logical, intent(in) :: colour_groups
        type(mesh_t), intent(out) :: mesh
        type(status_t), intent(out) :: st
        type(string_t), allocatable, intent(out) :: notes(:)
        character(len=:), allocatable :: text
        integer(i4), allocatable :: origin(:)
        call ideas_to_aster(path, colour_groups, text, origin, notes, st)
        if (st%failed()) return
        call read_aster_text(text, path, mesh, st)
        if (st%failed()) then   ! at the line of the universal file the .mail line came from
            if (allocated(st%file)) then
                if (st%file == path .and. st%line >= 1 .and. st%line <= size(origin)) &
                    st%line = origin(st%line)
            end if
        end if
    end subroutine read_ideas_mesh

    !> The .mail text of the universal file `path` (module header) and the line of the file
    !> each of its lines comes from.
    subroutine ideas_to_aster(path, colour_groups, text, origin, notes, st)
        character(len=*), intent(in) :: path
        logical, intent(in) :: colour_groups
        character(len=:), allocatable, intent(out) :: text
        integer(i4), allocatable, intent(out) :: origin(:)
        type(string_t), allocatable, intent(out) :: notes(:)
        type(status_t), intent(out) :: st
        type(work_t) :: w
        character(len=:), allocatable :: raw
        integer(i4) :: dataset
        logical :: ok
        allocate (notes(0), w%out(1024), w%origin(1024), w%system_label(0), w%system_type(0))
        text = ''
        call read_text_file(path, 'IDEAS mesh file', raw, st)
        if (st%failed()) return
        call split_text_lines(raw, w%lines)
        deallocate (raw)
        w%path = path
        w%colours = colour_groups
        call put(w, 'TITRE')
        call put(w, 'IDEAS (I-DEAS universal file)')
        call put(w, 'FINSF')
        do while (w%k < size(w%lines))
            w%k = w%k + 1
            if (.not. is_delimiter(w%lines(w%k)%s)) cycle
            if (w%k == size(w%lines)) exit
            if (is_delimiter(w%lines(w%k + 1)%s)) cycle   ! the end of the last one
            w%k = w%k + 1
            w%here = w%k
            call parse_integer(trim(adjustl(field(w%lines(w%k)%s, 1, 6))), dataset, ok)
            if (.not. ok) then
                call fail(w, 'a dataset number (I6) is expected after the line -1', st)
                return
            end if
            select case (dataset)
            case (2411, 781, 15)
                call read_nodes(w, dataset, notes, st)
            case (2412, 780)
                call read_cells(w, dataset, notes, st)
            case (752, 2417, 2429, 2430, 2432, 2435, 2452, 2467, 2477)
                call read_groups(w, dataset, notes, st)
            case (2420, 18)
                call read_systems(w, dataset, st)
            case (71, 82, 2431)
                call fail(w, 'dataset ' // to_text(dataset) // ' (cells of the older ' // &
                    'formats, trace lines) is not read by parasol: export the mesh with ' // &
                    'dataset 2412', st)
            case default
                notes = [notes, string_t('IDEAS: dataset ' // to_text(dataset) // ' at line ' // &
                    to_text(w%k) // ' not read (Code_Aster does not read it either)')]
                call skip_dataset(w, st)
            end select
            if (st%failed()) return
        end do
        if (.not. w%has_nodes) then
            w%k = size(w%lines, kind=i4)
            call fail(w, 'no nodes in the file (dataset 2411, 781 or 15; STBTRIAS_1): is ' // &
                'it an I-DEAS universal file?', st)
            return
        end if
        w%here = size(w%lines, kind=i4)
        call put(w, 'FIN')
        text = join_lines(w%out(1:w%n_out))
        origin = w%origin(1:w%n_out)
    end subroutine ideas_to_aster

    ! ---- datasets -----------------------------------------------------------------------

    ! Nodes: N<label> x y z, in the file's order.
    subroutine read_nodes(w, dataset, notes, st)
        type(work_t), intent(inout) :: w
        integer(i4), intent(in) :: dataset
        type(string_t), allocatable, intent(inout) :: notes(:)
        type(status_t), intent(inout) :: st
        integer(i4) :: head(4), label, system, j, n_labels, n_colours
        integer(i4), allocatable :: labels(:), colours(:)
        real(dp) :: x(3)
        character(len=24) :: number
        character(len=:), allocatable :: line
        logical :: mixed
        n_labels = 0
        n_colours = 0
        call put(w, 'COOR_3D')
        mixed = .false.
        do
            if (.not. next_line(w, st)) return
            if (is_delimiter(w%lines(w%k)%s)) exit
            w%here = w%k
            call fixed_ints(w, 4, 10, head, st)
            if (st%failed()) return
            label = head(1)
            if (label < 1) then
                call fail(w, 'node label ' // to_text(label) // ': labels are positive', st)
                return
            end if
            system = head(2)
            if (dataset == 15) then
                do j = 1, 3
                    call fixed_real(w, 41 + 13 * (j - 1), 13, x(j), st)
                end do
            else
                if (.not. next_line(w, st)) return
                do j = 1, 3
                    call fixed_real(w, 1 + 25 * (j - 1), 25, x(j), st)
                end do
            end if
            if (st%failed()) return
            if (system_type_of(w, system) /= 0) then
                call fail(w, 'node ' // to_text(label) // ' is given in coordinate system ' // &
                    to_text(system) // ', which is not cartesian: Code_Aster does not ' // &
                    'convert it (STBTRIAS_10); export the nodes in a cartesian system', st)
                return
            end if
            if (w%last_system /= -1 .and. system /= w%last_system) mixed = .true.
            w%last_system = system
            line = 'N' // to_text(label)
            do j = 1, 3
                write (number, '(1x, es23.15e3)') x(j)
                line = line // trim(number)
            end do
            call put(w, line)
            if (w%colours) then
                call push(labels, n_labels, [label])
                call push(colours, n_colours, [head(4)])
            end if
        end do
        call put(w, 'FINSF')
        w%has_nodes = .true.
        if (mixed) notes = [notes, string_t('IDEAS: the nodes are given in several ' // &
            'coordinate systems, their coordinates taken as they are (STBTRIAS_11)')]
        if (w%colours .and. n_labels > 0) call colour_groups(w, 'GROUP_NO', 'N', &
            labels(1:n_labels), colours(1:n_labels), notes)
    end subroutine read_nodes

    ! Cells: M<label> and its nodes, by kind in Code_Aster's order (module header).
    subroutine read_cells(w, dataset, notes, st)
        type(work_t), intent(inout) :: w
        integer(i4), intent(in) :: dataset
        type(string_t), allocatable, intent(inout) :: notes(:)
        type(status_t), intent(inout) :: st
        integer(i4), allocatable :: kind_of(:), label(:), colour(:), first(:), nodes(:), &
            cell_nodes(:), at(:)
        integer(i4) :: head(8), n_cells, descriptor, n_nodes, kind, c, j, line_no, n1, n2, &
            n3, n4, n5, n6
        character(len=:), allocatable :: line
        n_cells = 0
        n1 = 0
        n2 = 0
        n3 = 0
        n4 = 0
        n5 = 0
        n6 = 0
        call push(first, n5, [1])
        do
            if (.not. next_line(w, st)) return
            if (is_delimiter(w%lines(w%k)%s)) exit
            line_no = w%k
            if (dataset == 780) then
                call fixed_ints(w, 8, 10, head, st)
                if (st%failed()) return
                head(5) = head(7)
                head(6) = head(8)
            else
                call fixed_ints(w, 6, 10, head(1:6), st)
                if (st%failed()) return
            end if
            descriptor = head(2)
            n_nodes = head(6)
            if (head(1) < 1) then
                call fail(w, 'cell label ' // to_text(head(1)) // ': labels are positive', st)
                return
            end if
            kind = cell_kind(descriptor)
            if (kind == 0) then
                call fail(w, 'cell ' // to_text(head(1)) // ': FE descriptor ' // &
                    to_text(descriptor) // ' is not one Code_Aster converts (cov4v5)', st)
                return
            end if
            if (.not. KIND_PARASOL(kind)) then
                call fail(w, 'cell ' // to_text(head(1)) // ': FE descriptor ' // &
                    to_text(descriptor) // ' makes a ' // trim(KIND_NAMES(kind)) // ' cell: ' // &
                    'parasol''s meshes hold POI1, SEG2, SEG3, TRIA3, TRIA6, QUAD4 and QUAD8 ' // &
                    'cells from I-DEAS files', st)
                return
            end if
            if (n_nodes /= KIND_NODES(kind)) then
                call fail(w, 'cell ' // to_text(head(1)) // ': ' // to_text(n_nodes) // &
                    ' nodes for FE descriptor ' // to_text(descriptor) // ', a ' // &
                    trim(KIND_NAMES(kind)) // ' has ' // to_text(KIND_NODES(kind)), st)
                return
            end if
            if (any(BEAM_DESCRIPTORS == descriptor)) then
                if (.not. next_line(w, st)) return   ! beam orientation and sections
            end if
            call read_labels(w, n_nodes, cell_nodes, st)
            if (st%failed()) return
            n_cells = n_cells + 1
            call push(kind_of, n1, [kind])
            call push(label, n2, [head(1)])
            call push(colour, n3, [head(5)])
            call push(at, n4, [line_no])
            call push(nodes, n6, cell_nodes(kind_order(kind, n_nodes)))
            call push(first, n5, [n6 + 1])
        end do
        do kind = 1, N_KINDS
            if (.not. any(kind_of(1:n_cells) == kind)) cycle
            w%here = at(findloc(kind_of(1:n_cells), kind, dim=1))
            call put(w, trim(KIND_NAMES(kind)))
            do c = 1, n_cells
                if (kind_of(c) /= kind) cycle
                w%here = at(c)
                line = 'M' // to_text(label(c))
                do j = first(c), first(c + 1) - 1
                    line = line // ' N' // to_text(nodes(j))
                end do
                call put(w, line)
            end do
            call put(w, 'FINSF')
        end do
        if (w%colours .and. n_cells > 0) call colour_groups(w, 'GROUP_MA', 'M', &
            label(1:n_cells), colour(1:n_cells), notes)
    end subroutine read_cells

    ! Groups (module header): GROUP_NO and GROUP_MA of the nodes and cells each lists.
    subroutine read_groups(w, dataset, notes, st)
        type(work_t), intent(inout) :: w
        integer(i4), intent(in) :: dataset
        type(string_t), allocatable, intent(inout) :: notes(:)
        type(status_t), intent(inout) :: st
        integer(i4) :: number, n_entities, per_line, count_column, i, j, values(8), n_no, n_ma
        integer(i4), allocatable :: node_labels(:), cell_labels(:)
        character(len=:), allocatable :: full, name
        logical :: cells_written
        select case (dataset)
        case (752)
            count_column = 51     ! (I10, 40X, I10)
        case (2417)
            count_column = 61     ! (I10, 50X, I10)
        case default
            count_column = 71     ! (I10, 60X, I10)
        end select
        per_line = merge(2, 4, any(dataset == [2435, 2452, 2467, 2477]))
        do
            if (.not. next_line(w, st)) return
            if (is_delimiter(w%lines(w%k)%s)) exit
            w%here = w%k
            call fixed_int(w, 1, 10, number, st)
            if (st%ok()) call fixed_int(w, count_column, 10, n_entities, st)
            if (st%failed()) return
            if (n_entities < 0 .or. n_entities > 2 * size(w%lines)) then
                call fail(w, 'group ' // to_text(number) // ': ' // to_text(n_entities) // &
                    ' entities announced', st)
                return
            end if
            if (.not. next_line(w, st)) return
            full = trim(field(w%lines(w%k)%s, 1, 20))
            n_no = 0
            n_ma = 0
            i = 0
            do while (i < n_entities)
                if (.not. next_line(w, st)) return
                if (per_line == 2) then
                    do j = 1, min(2, n_entities - i)
                        call fixed_int(w, 1 + 40 * (j - 1), 10, values(2 * j - 1), st)
                        if (st%ok()) call fixed_int(w, 11 + 40 * (j - 1), 10, values(2 * j), st)
                    end do
                else
                    do j = 1, min(4, n_entities - i)
                        call fixed_int(w, 1 + 20 * (j - 1), 10, values(2 * j - 1), st)
                        if (st%ok()) call fixed_int(w, 11 + 20 * (j - 1), 10, values(2 * j), st)
                    end do
                end if
                if (st%failed()) return
                do j = 1, min(per_line, n_entities - i)
                    if (values(2 * j - 1) == 7) call push(node_labels, n_no, [values(2 * j)])
                    if (values(2 * j - 1) == 8) call push(cell_labels, n_ma, [values(2 * j)])
                end do
                i = i + per_line
            end do
            call group_name(full, name, notes)
            if (len(name) > 0) then
                if (len(full) >= 9) then
                    if (full(1:9) == 'PERMANENT') name = ''
                end if
                cells_written = .true.
                if (len(name) >= 5) cells_written = name(1:5) /= 'COUL_'
                if (.not. cells_written .and. n_ma > 0) notes = [notes, &
                    string_t('IDEAS: the cells of group ' // name // ' are not written: ' // &
                    'COUL_ names are those of CREA_GROUP_COUL (STBTRIAS_8)')]
                if (n_no > 0) call write_group(w, 'GROUP_NO', &
                    merge_name(name, 'GRNO', number), 'N', node_labels(1:n_no))
                if (n_ma > 0 .and. cells_written) call write_group(w, &
                    'GROUP_MA', merge_name(name, 'GRMA', number), 'M', cell_labels(1:n_ma))
            end if
        end do
    end subroutine read_groups

    ! Coordinate systems: the type (0 cartesian, 1 cylindrical, 2 spherical) of each label.
    subroutine read_systems(w, dataset, st)
        type(work_t), intent(inout) :: w
        integer(i4), intent(in) :: dataset
        type(status_t), intent(inout) :: st
        integer(i4) :: head(2), j
        deallocate (w%system_label, w%system_type)
        allocate (w%system_label(0), w%system_type(0))
        if (dataset == 2420) then
            if (.not. next_line(w, st)) return   ! part UID
            if (is_delimiter(w%lines(w%k)%s)) return
            if (.not. next_line(w, st)) return   ! part name
        end if
        do
            if (.not. next_line(w, st)) return
            if (is_delimiter(w%lines(w%k)%s)) exit
            call fixed_ints(w, 2, 10, head, st)
            if (st%failed()) return
            w%system_label = [w%system_label, head(1)]
            w%system_type = [w%system_type, head(2)]
            do j = 1, merge(5, 3, dataset == 2420)   ! its name and its matrix
                if (.not. next_line(w, st)) return
            end do
        end do
    end subroutine read_systems

    ! ---- the .mail ----------------------------------------------------------------------

    subroutine put(w, s)
        type(work_t), intent(inout) :: w
        character(len=*), intent(in) :: s
        if (w%n_out == size(w%out)) then
            w%out = [w%out, w%out]
            w%origin = [w%origin, w%origin]
        end if
        w%n_out = w%n_out + 1
        w%out(w%n_out)%s = s
        w%origin(w%n_out) = w%here
    end subroutine put

    ! A group of `labels` (prefix N or M), 8 a line.
    subroutine write_group(w, word, name, prefix, labels)
        type(work_t), intent(inout) :: w
        character(len=*), intent(in) :: word, name, prefix
        integer(i4), intent(in) :: labels(:)
        character(len=:), allocatable :: line
        integer(i4) :: i
        call put(w, word // ' NOM=' // name)
        line = ''
        do i = 1, size(labels, kind=i4)
            line = line // ' ' // prefix // to_text(labels(i))
            if (mod(i, 8) == 0 .or. i == size(labels)) then
                call put(w, line)
                line = ''
            end if
        end do
        call put(w, 'FINSF')
    end subroutine write_group

    ! CREA_GROUP_COUL: COUL_<c> of the entities of colour c, in increasing c (snecol, slecol).
    subroutine colour_groups(w, word, prefix, labels, colours, notes)
        type(work_t), intent(inout) :: w
        character(len=*), intent(in) :: word, prefix
        integer(i4), intent(in) :: labels(:), colours(:)
        type(string_t), allocatable, intent(inout) :: notes(:)
        integer(i4) :: c
        if (any(colours < 0 .or. colours > MAX_COLOUR)) notes = [notes, string_t('IDEAS: ' // &
            'colours beyond 0-255 make no COUL_ group (STBTRIAS_2)')]
        do c = 0, MAX_COLOUR
            if (.not. any(colours == c)) cycle
            call write_group(w, word, 'COUL_' // to_text(c), prefix, pack(labels, colours == c))
        end do
    end subroutine colour_groups

    ! ---- names --------------------------------------------------------------------------

    ! The group name Code_Aster gives `full` (slegro): its first 8 characters, cut to the
    ! name they start with; '' when they start with no name (the group is skipped).
    subroutine group_name(full, name, notes)
        character(len=*), intent(in) :: full
        character(len=:), allocatable, intent(out) :: name
        type(string_t), allocatable, intent(inout) :: notes(:)
        character(len=8) :: first8
        integer(i4) :: k, n
        first8 = adjustl(full)
        if (len_trim(full) > 8) notes = [notes, string_t('IDEAS: group name "' // full // &
            '" is longer than 8 characters: cut to 8 (STBTRIAS_5)')]
        name = ''
        if (.not. is_letter(first8(1:1))) then
            notes = [notes, string_t('IDEAS: group "' // full // '" is skipped: its name ' // &
                'does not start with a letter (STBTRIAS_6)')]
            return
        end if
        n = 1
        do k = 2, 8
            if (.not. (is_letter(first8(k:k)) .or. is_digit(first8(k:k)) .or. &
                       first8(k:k) == '_')) exit
            n = k
        end do
        name = first8(1:n)
        if (n /= len_trim(full) .and. len_trim(full) <= 8) notes = [notes, string_t( &
            'IDEAS: group name "' // full // '" read as ' // name // ' (STBTRIAS_7)')]
    end subroutine group_name

    function merge_name(name, prefix, number) result(s)
        character(len=*), intent(in) :: name, prefix
        integer(i4), intent(in) :: number
        character(len=:), allocatable :: s
        s = name
        if (len(s) == 0) s = prefix // to_text(number)
    end function merge_name

    pure logical function is_letter(c)
        character, intent(in) :: c
        is_letter = (c >= 'A' .and. c <= 'Z') .or. (c >= 'a' .and. c <= 'z')
    end function is_letter

    pure logical function is_digit(c)
        character, intent(in) :: c
        is_digit = c >= '0' .and. c <= '9'
    end function is_digit

    ! ---- reading ------------------------------------------------------------------------

    ! A dataset's delimiter: `-1` alone on its line (Code_Aster reads '    -1').
    pure logical function is_delimiter(line)
        character(len=*), intent(in) :: line
        is_delimiter = trim(adjustl(line)) == '-1'
    end function is_delimiter

    subroutine skip_dataset(w, st)
        type(work_t), intent(inout) :: w
        type(status_t), intent(inout) :: st
        do
            if (.not. next_line(w, st)) return
            if (is_delimiter(w%lines(w%k)%s)) return
        end do
    end subroutine skip_dataset

    ! n node labels, 8 a line (8I10).
    subroutine read_labels(w, n, values, st)
        type(work_t), intent(inout) :: w
        integer(i4), intent(in) :: n
        integer(i4), allocatable, intent(out) :: values(:)
        type(status_t), intent(inout) :: st
        integer(i4) :: i, j
        allocate (values(n))
        i = 0
        do while (i < n)
            if (.not. next_line(w, st)) return
            do j = 1, min(8, n - i)
                call fixed_int(w, 1 + 10 * (j - 1), 10, values(i + j), st)
                if (st%failed()) return
                if (values(i + j) < 1) then
                    call fail(w, 'node label ' // to_text(values(i + j)) // ': labels are ' // &
                              'positive', st)
                    return
                end if
            end do
            i = i + 8
        end do
    end subroutine read_labels

    subroutine fixed_ints(w, n, width, values, st)
        type(work_t), intent(inout) :: w
        integer(i4), intent(in) :: n, width
        integer(i4), intent(out) :: values(:)
        type(status_t), intent(inout) :: st
        integer(i4) :: j
        do j = 1, n
            call fixed_int(w, 1 + width * (j - 1), width, values(j), st)
            if (st%failed()) return
        end do
    end subroutine fixed_ints

    ! The integer in columns first .. first + width - 1 of the current line (blank: 0, as a
    ! Fortran I edit descriptor reads it).
    subroutine fixed_int(w, first, width, value, st)
        type(work_t), intent(inout) :: w
        integer(i4), intent(in) :: first, width
        integer(i4), intent(out) :: value
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: text
        logical :: ok
        value = 0
        text = trim(adjustl(field(w%lines(w%k)%s, first, width)))
        if (len(text) == 0) return
        call parse_integer(text, value, ok)
        if (.not. ok) call fail(w, '"' // text // '" is not an integer (columns ' // &
            to_text(first) // '-' // to_text(first + width - 1) // ')', st)
    end subroutine fixed_int

    subroutine fixed_real(w, first, width, value, st)
        type(work_t), intent(inout) :: w
        integer(i4), intent(in) :: first, width
        real(dp), intent(out) :: value
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: text
        logical :: ok
        value = 0.0_dp
        if (st%failed()) return
        text = trim(adjustl(field(w%lines(w%k)%s, first, width)))
        if (len(text) == 0) return
        call parse_real(text, value, ok)
        if (.not. ok) call fail(w, '"' // text // '" is not a real number (columns ' // &
            to_text(first) // '-' // to_text(first + width - 1) // ')', st)
    end subroutine fixed_real

    function field(line, first, w) result(text)
        character(len=*), intent(in) :: line
        integer(i4), intent(in) :: first, w
        character(len=w) :: text
        integer(i4) :: last
        text = ''
        last = min(len(line), first + w - 1)
        if (last >= first) text = line(first:last)
    end function field

    logical function next_line(w, st)
        type(work_t), intent(inout) :: w
        type(status_t), intent(inout) :: st
        next_line = w%k < size(w%lines)
        if (next_line) then
            w%k = w%k + 1
        else
            call fail(w, 'the file ends inside a dataset (no closing -1)', st)
        end if
    end function next_line

    integer(i4) function system_type_of(w, label) result(t)
        type(work_t), intent(in) :: w
        integer(i4), intent(in) :: label
        integer(i4) :: j
        t = 0
        do j = 1, size(w%system_label, kind=i4)
            if (w%system_label(j) == label) t = w%system_type(j)
        end do
    end function system_type_of

    ! Appends `values` to list(1:n), the list doubled when full (O(1) amortised).
    subroutine push(list, n, values)
        integer(i4), allocatable, intent(inout) :: list(:)
        integer(i4), intent(inout) :: n
        integer(i4), intent(in) :: values(:)
        integer(i4), allocatable :: grown(:)
        if (.not. allocated(list)) allocate (list(max(64, size(values))))
        if (n + size(values) > size(list)) then
            allocate (grown(max(2 * size(list), n + size(values))))
            grown(1:n) = list(1:n)
            call move_alloc(grown, list)
        end if
        list(n + 1:n + size(values)) = values
        n = n + size(values, kind=i4)
    end subroutine push

    subroutine fail(w, message, st)
        type(work_t), intent(in) :: w
        character(len=*), intent(in) :: message
        type(status_t), intent(inout) :: st
        call set_error(st, STATUS_MESH_ERROR, message, file=w%path, line=max(w%k, 1_i4))
    end subroutine fail

end module mesh_ideas_reader
