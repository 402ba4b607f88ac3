!> GIBI meshes (Cast3M's SAUVER format: LIRE_MAILLAGE FORMAT='GIBI', PRE_GIBI), converted as
!> Code_Aster's PRE_GIBI converts them (op0049: gilir2 reads, giecas writes the .mail), so
!> that nodes, cells and groups have Code_Aster's names and orders.
!>
!> The file is a sequence of records, each opened by a line `ENREGISTREMENT DE TYPE   n`:
!>   4  NIVEAU (the format's level), NIVEAU ERREUR, DIMENSION (1, 2, 3); DENSITE
!>   7  Cast3M's options (two lines, skipped)
!>   2  a pile of objects: ` PILE NUMERO   p NBRE OBJETS NOMMES  n NBRE OBJETS  m`
!>   5  the end
!> and the piles parasol reads (others are skipped line by line, as Code_Aster does):
!>   1   meshes (MAILLAGE objects): the n names (8 per line), the n object numbers they
!>       name, then the m objects; each: ITYPEL NBSOUS NBREF NBNOEL NBELEM, then for a
!>       composite (NBSOUS > 0) its sub-object numbers and NBREF references, for a simple one
!>       NBREF references, NBELEM colours and NBELEM x NBNOEL point numbers;
!>   32  points: n names and the points they name, the count m, then the node (of pile 33)
!>       of each point (the indirection);
!>   33  coordinates: the count of reals, then (x, y[, z], density) of each node;
!>   0   (older files) named points, then the coordinates directly.
!> Integers are in fixed fields (10 of 8 characters a line; 16 of 5 at level 3), names in
!> 8 fields of (1x, a8), reals in 3 fields of (1x, d21.14): Code_Aster's formats.
!>
!> The .mail written (giecas, giecma): nodes N<node of pile 33> for the nodes some point
!> uses, in increasing order (the others left out: PREPOST5_19); the cells of the named
!> objects and of their sub-objects, object by object, M<position among all cells> in
!> Cast3M's node order turned into Code_Aster's (giinco: quadratic cells list corners
!> first); a cell given again with the same nodes (Cast3M's ET) is written once, under the
!> name of the first written; the cells of unnamed objects are left out (PREPOST5_20);
!> GROUP_NO: each named point (names starting with # are Cast3M's own: skipped); GROUP_MA:
!> each named object, its cells or those of its sub-objects.
module mesh_gibi_reader
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MESH_ERROR
    use strings, only: string_t, to_text
    use text_file, only: read_text_file, split_text_lines
    use mesh_types, only: mesh_t
    use mesh_aster_reader, only: read_aster_text
    use mesh_text_lexer, only: parse_real, parse_integer
    use mesh_gibi_data, only: GIBI_CODES, GIBI_NAMES, ASTER_NAMES, TYPE_NODES, &
        N_PARASOL_TYPES, KNOWN_LEVELS, gibi_t, per_line, width, &
        objects_written, usable_name
    use mesh_gibi_writer, only: write_aster
    implicit none
    private

    public :: gibi_to_aster, read_gibi_mesh

    !> Lines of the file and the last one read.
    type :: cursor_t
        type(string_t), allocatable :: lines(:)
        integer(i4) :: k = 0
        character(len=:), allocatable :: path
    end type cursor_t

contains

    !> LIRE_MAILLAGE(FORMAT='GIBI'): the mesh PRE_GIBI would write, read as a .mail.
    !>  notes : out, lines for the .mess (nodes and cells left out, cells merged)
    !>  st    : STATUS_MESH_ERROR at the GIBI file's line for what the format does not allow,
    !>          for cells parasol has no type for; the .mail reader's errors after that (a
    !>          degenerate cell) name `PATH (as .mail)` and the cell
    subroutine read_gibi_mesh(path, mesh, st, notes)
        character(len=*), intent(in) :: path
        type(mesh_t), intent(out) :: mesh
        type(status_t), intent(out) :: st
        type(string_t), allocatable, intent(out) :: notes(:)
        character(len=:), allocatable :: text
        integer(i4), allocatable :: origin(:)
        call gibi_to_aster(path, text, notes, st, parasol_types=.true., origin=origin)
        if (st%failed()) return
        call read_aster_text(text, path, mesh, st)
        if (st%failed()) then   ! at the GIBI line the .mail line came from
            if (allocated(st%file)) then
                if (st%file == path .and. st%line >= 1 .and. st%line <= size(origin)) &
                    st%line = origin(st%line)
            end if
        end if
    end subroutine read_gibi_mesh

    !> PRE_GIBI: the .mail text of the GIBI file `path` (module header).
    !>  parasol_types : refuse cells of types parasol's meshes do not hold (volumes), at the
    !>                  line of their object (PRE_GIBI writes them: LIRE_MAILLAGE refuses them)
    !>  origin        : out, the line of the GIBI file each line of `text` comes from
    subroutine gibi_to_aster(path, text, notes, st, parasol_types, origin)
        character(len=*), intent(in) :: path
        character(len=:), allocatable, intent(out) :: text
        type(string_t), allocatable, intent(out) :: notes(:)
        type(status_t), intent(out) :: st
        logical, intent(in), optional :: parasol_types
        integer(i4), allocatable, intent(out), optional :: origin(:)
        integer(i4), allocatable :: lines_from(:)
        type(cursor_t) :: cur
        type(gibi_t), target :: g
        character(len=:), allocatable :: raw
        allocate (notes(0))
        text = ''
        call read_text_file(path, 'GIBI mesh file', raw, st)
        if (st%failed()) return
        call split_text_lines(raw, cur%lines)
        deallocate (raw)
        cur%path = path
        g%last_line = size(cur%lines, kind=i4)
        call read_records(cur, g, notes, st)
        if (st%failed()) return
        call check_references(cur, g, st)
        if (st%failed()) return
        if (present(parasol_types)) then
            if (parasol_types) call check_types(cur, g, st)
            if (st%failed()) return
        end if
        call write_aster(g, text, notes, lines_from)
        if (present(origin)) call move_alloc(lines_from, origin)
    end subroutine gibi_to_aster

    ! ---- reading ------------------------------------------------------------------------

    ! The records to type 5 (or the end of the file).
    subroutine read_records(cur, g, notes, st)
        type(cursor_t), intent(inout) :: cur
        type(gibi_t), intent(inout) :: g
        type(string_t), allocatable, intent(inout) :: notes(:)
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: line
        integer(i4) :: record, pile, n_named, n_objects, j
        logical :: seen_header, points_read, ended
        seen_header = .false.
        points_read = .false.
        ended = .false.
        if (size(cur%lines) == 0) then
            call fail(cur, 'the GIBI mesh file is empty', st)    ! PREPOST3_78
            return
        end if
        do while (cur%k < size(cur%lines))
            cur%k = cur%k + 1
            line = cur%lines(cur%k)%s
            if (.not. is_record(line, record)) then
                if (.not. seen_header) then
                    ! PREPOST3_75 / 77: not a file of SAUVER
                    call fail(cur, 'not a GIBI file of Cast3M''s SAUVER (its first line is ' &
                        // '" ENREGISTREMENT DE TYPE   4"; files of SORT are not read)', st)
                    return
                end if
                cycle
            end if
            seen_header = .true.
            select case (record)
            case (4)
                call read_general(cur, g, notes, st)
            case (7)
                cur%k = min(cur%k + 2, size(cur%lines, kind=i4))
            case (5)
                ended = .true.
                exit
            case (2)
                call read_pile_header(cur, g, pile, n_named, n_objects, st)
                if (st%failed()) return
                select case (pile)
                case (0)
                    if (allocated(g%coords)) then
                        call fail(cur, 'a second pile of coordinates', st)
                        return
                    end if
                    g%named_points_line = cur%k + 1
                    call read_named(cur, g, n_named, .false., g%point_names, g%named_points, &
                                    st)
                    if (st%ok()) call read_coordinates(cur, g, n_objects, st)
                    if (st%ok()) then
                        g%indirection = [(j, j = 1, size(g%coords, 2, kind=i4))]
                        g%has_indirection = .true.
                        points_read = .true.
                    end if
                case (32)
                    if (g%has_indirection .and. .not. points_read) then
                        call fail(cur, 'a second pile 32 (points)', st)
                    else if (.not. points_read) then
                        call read_points(cur, g, n_named, n_objects, st)
                    end if
                case (33)
                    if (allocated(g%coords)) then
                        call fail(cur, 'a second pile of coordinates', st)
                    else
                        call read_coordinate_pile(cur, g, st)
                    end if
                case (1)
                    if (allocated(g%objects)) then
                        call fail(cur, 'a second pile 1 (meshes)', st)
                        return
                    end if
                    g%pile1_line = cur%k
                    call read_named(cur, g, n_named, .true., g%object_names, g%named_objects, &
                                    st)
                    if (st%ok()) call read_objects(cur, g, n_objects, st)
                end select
            end select
            if (st%failed()) return
        end do
        if (g%dim == 0) then
            call fail(cur, 'no record of type 4 (NIVEAU, DIMENSION): the file is not a ' // &
                'GIBI mesh', st)
            return
        end if
        if (.not. allocated(g%objects)) allocate (g%objects(0))
        if (.not. allocated(g%object_names)) then
            allocate (g%object_names(0), g%named_objects(0))
        end if
        if (.not. allocated(g%point_names)) allocate (g%point_names(0), g%named_points(0))
        if (.not. allocated(g%coords)) then
            if (.not. ended) then
                call fail(cur, 'the file ends before its last record (type 5) and before ' // &
                    'the coordinates (pile 33): is it cut short?', st)
                return
            end if
            call fail(cur, 'no coordinates (pile 33) in the file', st)
            return
        end if
    end subroutine read_records

    ! True (and its type) when `line` opens a record: ` ENREGISTREMENT DE TYPE   n`.
    logical function is_record(line, record)
        character(len=*), intent(in) :: line
        integer(i4), intent(out) :: record
        logical :: ok
        record = 0
        is_record = .false.
        if (len(line) < 27) return
        if (line(2:15) /= 'ENREGISTREMENT' .or. line(20:23) /= 'TYPE') return
        call parse_integer(trim(adjustl(line(24:))), record, ok)
        is_record = ok
    end function is_record

    ! Record 4: ` NIVEAU  11 NIVEAU ERREUR   0 DIMENSION   2`, then the density line.
    subroutine read_general(cur, g, notes, st)
        type(cursor_t), intent(inout) :: cur
        type(gibi_t), intent(inout) :: g
        type(string_t), allocatable, intent(inout) :: notes(:)
        type(status_t), intent(inout) :: st
        integer(i4) :: values(3)
        if (.not. next_line(cur, st)) return
        call fixed_ints(cur, cur%lines(cur%k)%s, [8, 26, 40], [4, 4, 4], values, st)
        if (st%failed()) return
        g%level = values(1)
        g%dim = values(3)
        if (values(2) > 0) notes = [notes, string_t('GIBI: the file says NIVEAU ERREUR ' // &
            to_text(values(2)) // ': the mesh may be wrong (PREPOST_59)')]
        if (.not. any(KNOWN_LEVELS == g%level)) notes = [notes, string_t('GIBI: level ' // &
            'NIVEAU ' // to_text(g%level) // ' is not one Code_Aster knows (3 to 13): read ' // &
            'as level 11 (PREPOST3_76)')]
        if (g%dim < 2 .or. g%dim > 3) then
            call fail(cur, 'DIMENSION ' // to_text(g%dim) // ': parasol reads meshes of ' // &
                'dimension 2 or 3', st)
            return
        end if
        cur%k = min(cur%k + 1, size(cur%lines, kind=i4))   ! DENSITE
    end subroutine read_general

    ! ` PILE NUMERO   1NBRE OBJETS NOMMES      16NBRE OBJETS      32` (i5 counts to level 6).
    subroutine read_pile_header(cur, g, pile, n_named, n_objects, st)
        type(cursor_t), intent(inout) :: cur
        type(gibi_t), intent(in) :: g
        integer(i4), intent(out) :: pile, n_named, n_objects
        type(status_t), intent(inout) :: st
        integer(i4) :: values(3)
        pile = -1
        n_named = 0
        n_objects = 0
        if (.not. next_line(cur, st)) return
        if (g%level <= 6) then
            call fixed_ints(cur, cur%lines(cur%k)%s, [13, 35, 51], [4, 5, 5], values, st)
        else
            call fixed_ints(cur, cur%lines(cur%k)%s, [13, 35, 54], [4, 8, 8], values, st)
        end if
        if (st%failed()) return
        pile = values(1)
        n_named = values(2)
        n_objects = values(3)
        if (n_named < 0 .or. n_objects < 0) call fail(cur, 'negative count of objects', st)
    end subroutine read_pile_header

    ! The named objects of a pile: n names, then the n numbers they name (gilig0, gilig2).
    subroutine read_named(cur, g, n, of_objects, names, numbers, st)
        type(cursor_t), intent(inout) :: cur
        type(gibi_t), intent(in) :: g
        integer(i4), intent(in) :: n
        logical, intent(in) :: of_objects
        character(len=8), allocatable, intent(out) :: names(:)
        integer(i4), allocatable, intent(out) :: numbers(:)
        type(status_t), intent(inout) :: st
        integer(i4) :: k, i, line_count
        allocate (names(0), numbers(0))
        if (n == 0) return
        line_count = (n + 7) / 8
        if (line_count > size(cur%lines) - cur%k) then
            call fail(cur, to_text(n) // ' names announced, the file ends before', st)
            return
        end if
        deallocate (names)
        allocate (names(n))
        k = 0
        do while (k < n)
            if (.not. next_line(cur, st)) return
            do i = 1, min(8, n - k)
                names(k + i) = field(cur%lines(cur%k)%s, 2 + 9 * (i - 1), 8)
            end do
            k = k + min(8, n - k)
        end do
        ! gilig0 reads the numbers of objects as (1x, 10(i7, 1x)) or (16(1x, i4)), gilig2
        ! and gilig3 those of points as 10(i8) or 16(i5)
        if (of_objects .and. g%level == 3) then
            call read_ints(cur, n, 16, 1, 4, 5, numbers, st)
        else if (of_objects) then
            call read_ints(cur, n, 10, 1, 7, 8, numbers, st)
        else
            call read_ints(cur, n, per_line(g), 0, width(g), width(g), numbers, st)
        end if
    end subroutine read_named

    ! Pile 32: named points, the count, the node of each point (gilig3).
    subroutine read_points(cur, g, n_named, n_points, st)
        type(cursor_t), intent(inout) :: cur
        type(gibi_t), intent(inout) :: g
        integer(i4), intent(in) :: n_named, n_points
        type(status_t), intent(inout) :: st
        integer(i4), allocatable :: count(:)
        g%named_points_line = cur%k + 1
        call read_named(cur, g, n_named, .false., g%point_names, g%named_points, st)
        if (st%failed()) return
        call read_ints(cur, 1_i4, 1_i4, 0, 8, 8, count, st)
        if (st%failed()) return
        if (count(1) /= n_points) then
            call fail(cur, 'pile 32 announces ' // to_text(n_points) // ' points and lists ' &
                // to_text(count(1)), st)
            return
        end if
        g%points_line = cur%k + 1
        call read_ints(cur, n_points, per_line(g), 0, width(g), width(g), g%indirection, st)
        g%has_indirection = st%ok()
    end subroutine read_points

    ! Pile 33: ` nbval` (1x, i7), then the reals.
    subroutine read_coordinate_pile(cur, g, st)
        type(cursor_t), intent(inout) :: cur
        type(gibi_t), intent(inout) :: g
        type(status_t), intent(inout) :: st
        integer(i4), allocatable :: count(:)
        call read_ints(cur, 1_i4, 1_i4, 1, 7, 8, count, st)
        if (st%failed()) return
        if (count(1) < 0 .or. mod(count(1), g%dim + 1) /= 0) then
            call fail(cur, to_text(count(1)) // ' coordinates: not a multiple of ' // &
                to_text(g%dim + 1) // ' (DIMENSION coordinates and a density per node)', st)
            return
        end if
        call read_coordinates(cur, g, count(1) / (g%dim + 1), st)
    end subroutine read_coordinate_pile

    ! n_nodes x (dim + 1) reals, 3 a line (gilig1); the densities dropped.
    subroutine read_coordinates(cur, g, n_nodes, st)
        type(cursor_t), intent(inout) :: cur
        type(gibi_t), intent(inout) :: g
        integer(i4), intent(in) :: n_nodes
        type(status_t), intent(inout) :: st
        real(dp), allocatable :: values(:)
        integer(i4) :: n, k, i, j
        character(len=:), allocatable :: text
        logical :: ok
        n = n_nodes * (g%dim + 1)
        if ((n + 2) / 3 > size(cur%lines) - cur%k) then
            call fail(cur, to_text(n) // ' coordinates announced, the file ends before', st)
            return
        end if
        allocate (values(n))
        g%coords_line = cur%k + 1
        k = 0
        do while (k < n)
            if (.not. next_line(cur, st)) return
            do i = 1, min(3, n - k)
                text = trim(adjustl(field(cur%lines(cur%k)%s, 2 + 22 * (i - 1), 21)))
                if (len(text) == 0) then
                    values(k + i) = 0.0_dp
                    cycle
                end if
                call parse_real(text, values(k + i), ok)
                if (.not. ok .or. .not. (abs(values(k + i)) <= huge(1.0_dp))) then
                    call fail(cur, '"' // text // '" is not a real number', st)
                    return
                end if
            end do
            k = k + min(3, n - k)
        end do
        allocate (g%coords(g%dim, n_nodes))
        do j = 1, n_nodes
            g%coords(:, j) = values((j - 1) * (g%dim + 1) + 1:(j - 1) * (g%dim + 1) + g%dim)
        end do
    end subroutine read_coordinates

    ! The n objects of pile 1 (gilio2).
    subroutine read_objects(cur, g, n, st)
        type(cursor_t), intent(inout) :: cur
        type(gibi_t), intent(inout) :: g
        integer(i4), intent(in) :: n
        type(status_t), intent(inout) :: st
        integer(i4) :: i, t, n_ref
        integer(i4), allocatable :: skipped(:), h(:)
        if (n > size(cur%lines) - cur%k) then
            call fail(cur, to_text(n) // ' objects announced, the file ends before', st)
            return
        end if
        allocate (g%objects(n))
        do i = 1, n
            associate (o => g%objects(i))
                call read_ints(cur, 5_i4, 5_i4, 0, width(g), width(g), h, st)
                if (st%failed()) return
                o%line = cur%k
                if (any(h(2:5) < 0)) then
                    call fail(cur, 'object ' // to_text(i) // ': negative count', st)
                    return
                end if
                n_ref = h(3)
                if (h(2) > 0) then     ! composite: its sub-objects, its references
                    o%kind = 0
                    call read_ints(cur, h(2), per_line(g), 0, width(g), width(g), o%sub, st)
                    if (st%ok()) call read_ints(cur, n_ref, per_line(g), 0, width(g), &
                                                width(g), skipped, st)
                    if (st%failed()) return
                    allocate (o%points(0))
                    cycle
                end if
                if (h(1) == 0) then
                    call fail(cur, 'object ' // to_text(i) // ': a composite object ' // &
                        '(type 0) of no sub-object (PREPOST4_95)', st)
                    return
                end if
                t = findloc(GIBI_CODES, h(1), dim=1)
                if (t == 0) then
                    call fail(cur, 'object ' // to_text(i) // ': unknown GIBI element type ' // &
                        to_text(h(1)) // ' (PREPOST4_94)', st)
                    return
                end if
                if (h(4) /= TYPE_NODES(t)) then
                    call fail(cur, 'object ' // to_text(i) // ': ' // GIBI_NAMES(t) // &
                        ' cells have ' // to_text(TYPE_NODES(t)) // ' nodes, not ' // &
                        to_text(h(4)), st)
                    return
                end if
                o%kind = t
                o%n_nodes = h(4)
                o%n_cells = h(5)
                allocate (o%sub(0))
                call read_ints(cur, n_ref, per_line(g), 0, width(g), width(g), skipped, st)
                if (st%ok()) call read_ints(cur, o%n_cells, per_line(g), 0, width(g), &
                                            width(g), skipped, st)             ! colours
                if (st%failed()) return
                if (int(o%n_cells, i8) * o%n_nodes > int(huge(1_i4), i8)) then
                    call fail(cur, 'object ' // to_text(i) // ': too many cells', st)
                    return
                end if
                o%points_line = cur%k + 1
                call read_ints(cur, o%n_cells * o%n_nodes, per_line(g), 0, width(g), &
                               width(g), o%points, st)
                if (st%failed()) return
            end associate
        end do
    end subroutine read_objects

    ! n integers in fixed fields, `count` a line: the field i of a line at columns
    ! offset + (i-1)*stride + 1 .. + w. A blank field is 0 (Fortran's BN).
    subroutine read_ints(cur, n, count, offset, w, stride, values, st)
        type(cursor_t), intent(inout) :: cur
        integer(i4), intent(in) :: n, count, offset, w, stride
        integer(i4), allocatable, intent(out) :: values(:)
        type(status_t), intent(inout) :: st
        integer(i4) :: k, i
        character(len=:), allocatable :: text
        logical :: ok
        allocate (values(0))
        if (n <= 0) return
        if ((int(n, i8) + count - 1) / count > int(size(cur%lines) - cur%k, i8)) then
            call fail(cur, to_text(n) // ' numbers announced, the file ends before', st)
            return
        end if
        deallocate (values)
        allocate (values(n))
        k = 0
        do while (k < n)
            if (.not. next_line(cur, st)) return
            do i = 1, min(count, n - k)
                text = trim(adjustl(field(cur%lines(cur%k)%s, offset + (i - 1) * stride + 1, &
                                          w)))
                values(k + i) = 0
                if (len(text) == 0) cycle
                call parse_integer(text, values(k + i), ok)
                if (.not. ok) then
                    call fail(cur, '"' // text // '" is not an integer (columns ' // &
                        to_text(offset + (i - 1) * stride + 1) // '-' // &
                        to_text(offset + (i - 1) * stride + w) // ')', st)
                    return
                end if
            end do
            k = k + min(count, n - k)
        end do
    end subroutine read_ints

    ! The integers of one line at the given columns and widths.
    subroutine fixed_ints(cur, line, columns, widths, values, st)
        type(cursor_t), intent(in) :: cur
        character(len=*), intent(in) :: line
        integer(i4), intent(in) :: columns(:), widths(:)
        integer(i4), intent(out) :: values(:)
        type(status_t), intent(inout) :: st
        integer(i4) :: i, w
        character(len=:), allocatable :: text
        logical :: ok
        values = 0
        do i = 1, size(columns)
            w = widths(i)
            text = trim(adjustl(field(line, columns(i), w)))
            if (len(text) == 0) cycle
            call parse_integer(text, values(i), ok)
            if (.not. ok) then
                call fail(cur, '"' // text // '" is not an integer (columns ' // &
                    to_text(columns(i)) // '-' // to_text(columns(i) + w - 1) // ')', st)
                return
            end if
        end do
    end subroutine fixed_ints

    ! Columns first .. first + w - 1 of `line` (blank beyond its end).
    function field(line, first, w) result(text)
        character(len=*), intent(in) :: line
        integer(i4), intent(in) :: first, w
        character(len=w) :: text
        integer(i4) :: last
        text = ''
        last = min(len(line), first + w - 1)
        if (last >= first) text = line(first:last)
    end function field

    logical function next_line(cur, st)
        type(cursor_t), intent(inout) :: cur
        type(status_t), intent(inout) :: st
        next_line = cur%k < size(cur%lines)
        if (next_line) then
            cur%k = cur%k + 1
        else
            call fail(cur, 'the file ends inside a record', st)
        end if
    end function next_line


    subroutine fail(cur, message, st)
        type(cursor_t), intent(in) :: cur
        character(len=*), intent(in) :: message
        type(status_t), intent(inout) :: st
        call set_error(st, STATUS_MESH_ERROR, message, file=cur%path, line=max(cur%k, 1_i4))
    end subroutine fail

    ! ---- checks -------------------------------------------------------------------------

    ! Every number that names something names something that is there.
    subroutine check_references(cur, g, st)
        type(cursor_t), intent(inout) :: cur
        type(gibi_t), intent(in) :: g
        type(status_t), intent(inout) :: st
        integer(i4) :: i, n_obj, n_points, n_nodes
        n_obj = size(g%objects, kind=i4)
        n_nodes = size(g%coords, 2, kind=i4)
        if (.not. g%has_indirection) then
            cur%k = max(g%pile1_line, 1_i4)
            call fail(cur, 'no points (pile 32): the cells cannot be given nodes (PREPOST_55)', &
                      st)
            return
        end if
        n_points = size(g%indirection, kind=i4)
        if (any(g%indirection < 1 .or. g%indirection > n_nodes)) then
            cur%k = max(g%points_line, 1_i4)
            call fail(cur, 'a point of pile 32 is node ' // to_text(minval(g%indirection, &
                mask=g%indirection < 1 .or. g%indirection > n_nodes)) // ', the file has ' // &
                to_text(n_nodes) // ' nodes (pile 33)', st)
            return
        end if
        do i = 1, size(g%object_names, kind=i4)
            if (.not. usable_name(g%object_names(i))) then
                cur%k = g%pile1_line + 1 + (i - 1) / 8
                call fail(cur, 'the object name "' // trim(g%object_names(i)) // '" cannot ' &
                    // 'name a group (a blank, comma, tab or % in it, or no name)', st)
                return
            end if
        end do
        do i = 1, size(g%point_names, kind=i4)
            if (.not. usable_name(g%point_names(i))) then
                cur%k = max(g%named_points_line, 1_i4) + (i - 1) / 8
                call fail(cur, 'the point name "' // trim(g%point_names(i)) // '" cannot ' &
                    // 'name a group (a blank, comma, tab or % in it, or no name)', st)
                return
            end if
        end do
        do i = 1, size(g%named_objects, kind=i4)
            if (g%named_objects(i) < 1 .or. g%named_objects(i) > n_obj) then
                cur%k = max(g%pile1_line, 1_i4)
                call fail(cur, 'the name ' // trim(g%object_names(i)) // ' is given to ' // &
                    'object ' // to_text(g%named_objects(i)) // ', the pile has ' // &
                    to_text(n_obj), st)
                return
            end if
        end do
        do i = 1, n_obj
            associate (o => g%objects(i))
                cur%k = o%line
                if (any(o%sub < 1 .or. o%sub > n_obj)) then
                    call fail(cur, 'object ' // to_text(i) // ' is made of an object that ' // &
                        'is not in the pile', st)
                    return
                end if
                if (any(o%points < 1 .or. o%points > n_points)) then
                    call fail(cur, 'object ' // to_text(i) // ': a cell uses point ' // &
                        to_text(minval(o%points, mask=o%points < 1 .or. o%points > n_points)) &
                        // ', the file has ' // to_text(n_points) // ' points (pile 32)', st)
                    return
                end if
            end associate
        end do
        do i = 1, size(g%named_points, kind=i4)
            if (g%named_points(i) < 1 .or. g%named_points(i) > n_points) then
                cur%k = max(g%named_points_line, 1_i4)
                call fail(cur, 'the name ' // trim(g%point_names(i)) // ' is given to point ' &
                    // to_text(g%named_points(i)) // ', the file has ' // to_text(n_points), &
                    st)
                return
            end if
        end do
    end subroutine check_references

    ! The cells written (module header) are of parasol's types.
    subroutine check_types(cur, g, st)
        type(cursor_t), intent(inout) :: cur
        type(gibi_t), intent(in) :: g
        type(status_t), intent(inout) :: st
        logical, allocatable :: written(:)
        integer(i4) :: i
        written = objects_written(g)
        do i = 1, size(g%objects, kind=i4)
            if (.not. written(i) .or. g%objects(i)%kind <= N_PARASOL_TYPES) cycle
            if (g%objects(i)%n_cells == 0) cycle
            cur%k = g%objects(i)%line
            call fail(cur, 'object ' // to_text(i) // ': ' // &
                trim(ASTER_NAMES(g%objects(i)%kind)) // ' cells (GIBI ' // &
                GIBI_NAMES(g%objects(i)%kind) // '): parasol''s meshes hold POI1, SEG2, ' // &
                'SEG3, TRIA3, TRIA6, QUAD4, QUAD8 and QUAD9 cells', st)
            return
        end do
    end subroutine check_types


end module mesh_gibi_reader
