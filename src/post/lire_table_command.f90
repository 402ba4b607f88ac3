!> LIRE_TABLE (U7.02.03): a table read from the text file of UNITE, as Code_Aster's
!> lire_table_ops and TableReader read it:
!>  - FORMAT='LIBRE': fields split at runs of SEPARATEUR (default one blank); blank lines
!>    are dropped; a table (NUME_TABLE, default the first) is a block of lines, a new one
!>    starting where a line has fewer fields than the line before; in a block the lines
!>    with the most fields are the table (the first of them the column names), the others
!>    its title;
!>  - FORMAT='TABLEAU' (default): the same, lines starting with '#' being comments (title)
!>    and '-' an absent cell (what IMPR_TABLE writes);
!>  - FORMAT='ASTER': between #DEBUT_TABLE and #FIN_TABLE, #TITRE lines, the names, the
!>    types (I, R, K8 ...), then rows whose K fields have exactly their width.
!> A value is an integer, else a real (a decimal comma is read too), else a text (as
!> Python's int(), float()); a column's type follows its values (integers and reals make
!> a real column; a text among numbers is an error naming the row). Blanks in names
!> become '_'; RENOMME_PARA='UNIQUE' renames repeated names X, X_1, X_2, ... (otherwise
!> they are an error). Every error names the file and line.
module lire_table_command
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use, intrinsic :: ieee_exceptions, only: ieee_get_halting_mode, ieee_set_halting_mode, &
        ieee_overflow
    use kinds, only: dp, i4, i8
    use strings, only: string_t, to_text, to_lower
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_IO_ERROR
    use deck_concept, only: concept_t
    use deck_command, only: command_t
    use deck_value, only: append_string
    use run_context, only: run_context_t
    use text_file, only: read_text_file, split_text_lines
    use table_concept, only: table_t, table_init, table_add_column, table_add_rows, &
        table_set_int, table_set_real, table_set_text, table_append_title, TABLE_INT, &
        TABLE_REAL, TABLE_TEXT, TABLE_DEFAULT_TEXT_WIDTH, table_text_width_for, &
        MAX_TABLE_ROWS
    use table_keywords, only: relocate_at
    use unit_files, only: unit_input_path
    implicit none
    private

    !> Kinds of a read value.
    integer, parameter :: V_ABSENT = 0, V_INT = 1, V_REAL = 2, V_TEXT = 3, V_OVERFLOW = 4

    !> One read value.
    type :: cell_text_t
        integer :: kind = V_ABSENT
        integer(i8) :: i = 0
        real(dp) :: r = 0.0_dp
        character(len=:), allocatable :: k
    end type cell_text_t

    public :: run_lire_table

contains

    !> Handler of LIRE_TABLE.
    subroutine run_lire_table(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(table_t), allocatable :: t
        type(string_t), allocatable :: lines(:), titles(:)
        character(len=:), allocatable :: path, format, separator, text
        integer :: unit, block
        logical :: unique
        call cmd%get_int('UNITE', unit, st)
        if (st%ok()) call cmd%get_text('FORMAT', format, st)
        if (st%ok()) call cmd%get_int('NUME_TABLE', block, st)
        if (st%failed()) return
        separator = ' '
        if (cmd%has('SEPARATEUR')) call cmd%get_text('SEPARATEUR', separator, st)
        if (st%failed()) return
        if (len(separator) == 0) then
            call cmd%error_at('SEPARATEUR', 'the separator cannot be empty', st)
            return
        end if
        unique = cmd%has('RENOMME_PARA')
        call unit_input_path(ctx, unit, path, st)
        if (st%ok()) call read_text_file(path, 'table file', text, st)
        if (st%failed()) then
            call relocate_at(cmd, 'UNITE', st)
            return
        end if
        call split_text_lines(text, lines)
        allocate (t)
        call table_init(t)
        if (format == 'ASTER') then
            call read_aster(lines, separator, block, unique, path, t, st)
        else
            call read_free(lines, separator, format == 'TABLEAU', block, unique, path, t, st)
        end if
        if (st%failed()) then
            if (.not. allocated(st%command)) st%command = 'LIRE_TABLE'
            return
        end if
        if (cmd%has('TITRE')) then
            call cmd%get_texts('TITRE', titles, st)
            if (st%failed()) return
            deallocate (t%title)
            allocate (t%title(0))
            call table_append_title(t, titles(1)%s)
        end if
        if (.not. ctx%checking) call ctx%write_mess('    LIRE_TABLE: ' // &
            to_text(int(t%n_rows, i4)) // ' rows, ' // to_text(int(t%n_columns, i4)) // &
            ' columns read from ' // path)
        call move_alloc(t, result)
    end subroutine run_lire_table

    ! ---- LIBRE and TABLEAU -------------------------------------------------------------

    !> Blocks of lines, the table's lines and its names, then the rows.
    subroutine read_free(lines, separator, tableau, block, unique, path, t, st)
        type(string_t), intent(in) :: lines(:)
        character(len=*), intent(in) :: separator, path
        logical, intent(in) :: tableau, unique
        integer, intent(in) :: block
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        integer, allocatable :: counts(:), kept(:), starts(:)
        logical, allocatable :: comment(:)
        type(string_t), allocatable :: names(:)
        integer :: k, n, first, last, nb, width, header, b, n_blocks
        logical :: has_value
        ! the non-blank lines and their field counts (comments count 0 until a value)
        allocate (kept(size(lines)), counts(size(lines)), comment(size(lines)))
        n = 0
        do k = 1, size(lines)
            if (len_trim(strip_chars(lines(k)%s, ' ' // achar(9) // achar(13))) == 0) cycle
            n = n + 1
            kept(n) = k
            comment(n) = tableau .and. starts_with_hash(lines(k)%s)
            counts(n) = size(split_fields(lines(k)%s, separator))
        end do
        kept = kept(1:n)
        counts = counts(1:n)
        comment = comment(1:n)
        ! blocks: a line with fewer fields than the line before starts a new one
        allocate (starts(n + 1))
        starts(1) = 1
        n_blocks = 1
        nb = 0
        has_value = .false.
        do k = 1, size(kept)
            n = counts(k)
            if (comment(k) .and. .not. has_value) then
                n = 0
            else if (nb > 1 .and. n < nb) then
                n_blocks = n_blocks + 1
                starts(n_blocks) = k
                has_value = .false.
            end if
            counts(k) = n
            nb = n
            if (.not. comment(k)) has_value = .true.
        end do
        starts = starts(1:n_blocks)
        if (block > size(starts)) then
            call set_error(st, STATUS_MODEL_ERROR, 'NUME_TABLE=' // to_text(int(block, i4)) // &
                ': ' // path // ' holds ' // to_text(int(size(starts), i4)) // &
                ' table(s)', file=path)
            return
        end if
        first = starts(block)
        last = size(kept)
        if (block < size(starts)) last = starts(block + 1) - 1
        if (last < first) then
            call set_error(st, STATUS_MODEL_ERROR, path // ' holds no table', file=path)
            return
        end if
        width = maxval(counts(first:last))
        header = 0
        do k = first, last
            b = kept(k)
            if (counts(k) == width .and. .not. comment(k)) then
                if (header == 0) then
                    header = k
                    names = split_fields(lines(b)%s, separator)
                    call clean_names(names, unique, path, b, st)
                    if (st%failed()) return
                    call add_columns(t, names, path, b, st)
                    if (st%failed()) return
                else
                    call add_row(t, split_fields(lines(b)%s, separator), tableau, path, b, st)
                    if (st%failed()) return
                end if
            else
                call add_title_line(t, lines(b)%s, tableau)
            end if
        end do
        if (header == 0) call set_error(st, STATUS_MODEL_ERROR, path // ' holds no line of ' // &
            'column names', file=path)
    end subroutine read_free

    !> A comment or title line, without its '#' and the heading's dashes.
    subroutine add_title_line(t, line, tableau)
        type(table_t), intent(inout) :: t
        character(len=*), intent(in) :: line
        logical, intent(in) :: tableau
        character(len=:), allocatable :: text
        text = line
        if (tableau .and. starts_with_hash(text)) text = text(2:)
        text = trim(text)
        if (len(text) == 0 .or. verify(text, '-') == 0) return
        call table_append_title(t, text)
    end subroutine add_title_line

    pure logical function starts_with_hash(line)
        character(len=*), intent(in) :: line
        starts_with_hash = .false.
        if (len(line) > 0) starts_with_hash = line(1:1) == '#'
    end function starts_with_hash

    ! ---- ASTER ---------------------------------------------------------------------------

    !> The NUME_TABLE-th #DEBUT_TABLE .. #FIN_TABLE: #TITRE lines, names, types, rows.
    subroutine read_aster(lines, separator, block, unique, path, t, st)
        type(string_t), intent(in) :: lines(:)
        character(len=*), intent(in) :: separator, path
        integer, intent(in) :: block
        logical, intent(in) :: unique
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: names(:), types(:)
        type(cell_text_t), allocatable :: cells(:)
        integer :: k, found, first, last, stage
        found = 0
        first = 0
        last = 0
        do k = 1, size(lines)
            if (trim(lines(k)%s) == '#DEBUT_TABLE') then
                found = found + 1
                if (found == block) first = k + 1
            else if (trim(lines(k)%s) == '#FIN_TABLE' .and. first > 0 .and. last == 0) then
                last = k - 1
            end if
        end do
        if (first == 0 .or. last == 0) then
            call set_error(st, STATUS_MODEL_ERROR, 'NUME_TABLE=' // to_text(int(block, i4)) // &
                ': ' // path // ' holds ' // to_text(int(found, i4)) // ' complete ' // &
                'table(s) between #DEBUT_TABLE and #FIN_TABLE', file=path)
            return
        end if
        stage = 0
        do k = first, last
            if (len_trim(strip_chars(lines(k)%s, separator)) == 0) cycle
            if (index(lines(k)%s, '#TITRE') == 1) then
                call table_append_title(t, strip_chars(lines(k)%s(7:), separator))
                cycle
            end if
            select case (stage)
            case (0)
                names = split_fields(lines(k)%s, separator)
                call clean_names(names, unique, path, k, st)
                if (st%failed()) return
            case (1)
                types = split_fields(lines(k)%s, separator)
                call aster_columns(t, names, types, path, k, st)
                if (st%failed()) return
            case default
                call aster_fields(lines(k)%s, separator, t, cells, path, k, st)
                if (st%ok()) call store_row(t, cells, path, k, st)
                if (st%failed()) return
            end select
            stage = min(stage + 1, 2)
        end do
        if (stage < 2 .and. t%n_columns == 0) call set_error(st, STATUS_MODEL_ERROR, path // &
            ': the table has no line of names and types', file=path, line=first)
    end subroutine read_aster

    !> The columns of an ASTER table from its names and types.
    subroutine aster_columns(t, names, types, path, line, st)
        type(table_t), intent(inout) :: t
        type(string_t), intent(in) :: names(:), types(:)
        character(len=*), intent(in) :: path
        integer, intent(in) :: line
        type(status_t), intent(inout) :: st
        integer :: k, c, width, ios
        if (size(types) /= size(names)) then
            call set_error(st, STATUS_MODEL_ERROR, to_text(int(size(types), i4)) // &
                ' types for ' // to_text(int(size(names), i4)) // ' column names', &
                file=path, line=line)
            return
        end if
        do k = 1, size(names)
            select case (types(k)%s(1:1))
            case ('I')
                call table_add_column(t, names(k)%s, TABLE_INT, c, st)
            case ('R')
                call table_add_column(t, names(k)%s, TABLE_REAL, c, st)
            case ('K')
                read (types(k)%s(2:), *, iostat=ios) width
                if (ios /= 0 .or. len(types(k)%s) < 2 .or. &
                    verify(types(k)%s(2:), '0123456789') /= 0) width = 0
                if (table_text_width_for(width) /= width .or. width == 0) then
                    call set_error(st, STATUS_MODEL_ERROR, 'column ' // names(k)%s // &
                        ': type ' // types(k)%s // ' is not K8, K16, K24, K32 or K80', &
                        file=path, line=line)
                    return
                end if
                call table_add_column(t, names(k)%s, TABLE_TEXT, c, st, width)
            case default
                call set_error(st, STATUS_MODEL_ERROR, 'column ' // names(k)%s // ': type ' &
                    // types(k)%s // ' is not I, R or Kn', file=path, line=line)
                return
            end select
            if (st%failed()) then
                st%file = path
                st%line = line
                return
            end if
        end do
    end subroutine aster_columns

    !> The fields of an ASTER row: I and R as runs of their characters, Kn as exactly n
    !> characters, separators between them.
    subroutine aster_fields(line, separator, t, cells, path, number, st)
        character(len=*), intent(in) :: line, separator, path
        type(table_t), intent(in) :: t
        type(cell_text_t), allocatable, intent(out) :: cells(:)
        integer, intent(in) :: number
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: allowed, field
        integer :: c, p, q
        allocate (cells(t%n_columns))
        p = 1
        do c = 1, t%n_columns
            do while (p <= len(line))             ! separators before the field
                if (index(separator, line(p:p)) == 0) exit
                p = p + 1
            end do
            if (t%columns(c)%kind == TABLE_TEXT) then
                if (p + t%columns(c)%width - 1 > len(line)) then
                    field = line(p:)
                else
                    field = line(p:p + t%columns(c)%width - 1)
                end if
                p = p + len(field)
            else
                allowed = '0123456789+-'
                if (t%columns(c)%kind == TABLE_REAL) allowed = '0123456789.,+-eEdD'
                q = p
                do while (q <= len(line))
                    if (index(allowed, line(q:q)) == 0) exit
                    q = q + 1
                end do
                field = line(p:q - 1)
                p = q
            end if
            if (len(field) == 0) then
                call set_error(st, STATUS_MODEL_ERROR, 'the row has ' // &
                    to_text(int(c - 1, i4)) // ' fields where the table has ' // &
                    to_text(int(t%n_columns, i4)) // ' columns (' // t%columns(c)%name // &
                    ' is missing)', file=path, line=number)
                return
            end if
            call parse_cell(trim(adjustl(field)), .true., t%columns(c)%kind == TABLE_TEXT, &
                            cells(c))
        end do
        if (len_trim(strip_chars(line(min(p, len(line) + 1):), separator)) > 0) &
            call set_error(st, STATUS_MODEL_ERROR, 'the row has more fields than the ' // &
            'table''s ' // to_text(int(t%n_columns, i4)) // ' columns', file=path, line=number)
    end subroutine aster_fields

    ! ---- shared ------------------------------------------------------------------------

    !> Names without blanks ('_'), unique (RENOMME_PARA='UNIQUE') or an error.
    subroutine clean_names(names, unique, path, line, st)
        type(string_t), intent(inout) :: names(:)
        logical, intent(in) :: unique
        character(len=*), intent(in) :: path
        integer, intent(in) :: line
        type(status_t), intent(inout) :: st
        integer :: k, j, suffix
        character(len=:), allocatable :: candidate
        do k = 1, size(names)
            names(k)%s = trim(adjustl(names(k)%s))
            do j = 1, len(names(k)%s)
                if (names(k)%s(j:j) == ' ' .or. names(k)%s(j:j) == achar(9)) &
                    names(k)%s(j:j) = '_'
            end do
            if (len(names(k)%s) == 0) then
                call set_error(st, STATUS_MODEL_ERROR, 'column ' // to_text(int(k, i4)) // &
                    ' has no name', file=path, line=line)
                return
            end if
        end do
        do k = 2, size(names)
            if (.not. any([(names(j)%s == names(k)%s, j=1, k - 1)])) cycle
            if (.not. unique) then
                call set_error(st, STATUS_MODEL_ERROR, 'column name ' // names(k)%s // &
                    ' is given twice (RENOMME_PARA=''UNIQUE'' renames repeated names)', &
                    file=path, line=line)
                return
            end if
            suffix = 0
            candidate = names(k)%s
            do while (any([(names(j)%s == candidate, j=1, k - 1)]))
                suffix = suffix + 1
                candidate = names(k)%s // '_' // to_text(int(suffix, i4))
            end do
            names(k)%s = candidate
        end do
    end subroutine clean_names

    !> Columns of a LIBRE or TABLEAU table: their types come from their values (add_row).
    subroutine add_columns(t, names, path, line, st)
        type(table_t), intent(inout) :: t
        type(string_t), intent(in) :: names(:)
        character(len=*), intent(in) :: path
        integer, intent(in) :: line
        type(status_t), intent(inout) :: st
        integer :: k, c
        do k = 1, size(names)
            ! no value yet: an integer column, which reals promote (texts retype it)
            call table_add_column(t, names(k)%s, TABLE_INT, c, st)
            if (st%failed()) then
                st%file = path
                st%line = line
                return
            end if
        end do
    end subroutine add_columns

    !> A row of a LIBRE or TABLEAU table.
    subroutine add_row(t, fields, tableau, path, line, st)
        type(table_t), intent(inout) :: t
        type(string_t), intent(in) :: fields(:)
        logical, intent(in) :: tableau
        character(len=*), intent(in) :: path
        integer, intent(in) :: line
        type(status_t), intent(inout) :: st
        type(cell_text_t), allocatable :: cells(:)
        integer :: k
        allocate (cells(t%n_columns))
        do k = 1, min(size(fields), t%n_columns)
            call parse_cell(trim(adjustl(fields(k)%s)), tableau, .false., cells(k))
        end do
        call store_row(t, cells, path, line, st)
    end subroutine add_row

    !> Appends a row; a column's type follows its values (an integer column without a value
    !> yet becomes a text or real column; integers and reals make reals).
    subroutine store_row(t, cells, path, line, st)
        type(table_t), intent(inout) :: t
        type(cell_text_t), intent(in) :: cells(:)
        character(len=*), intent(in) :: path
        integer, intent(in) :: line
        type(status_t), intent(inout) :: st
        integer :: k, r
        if (t%n_rows >= MAX_TABLE_ROWS) then
            call set_error(st, STATUS_MODEL_ERROR, 'a table has at most ' // &
                to_text(int(MAX_TABLE_ROWS, i4)) // ' rows', file=path, line=line)
            return
        end if
        call table_add_rows(t, 1)
        r = t%n_rows
        do k = 1, size(cells)
            if (cells(k)%kind == V_ABSENT) cycle
            if (cells(k)%kind == V_OVERFLOW) then
                call set_error(st, STATUS_MODEL_ERROR, 'column ' // t%columns(k)%name // &
                    ': ' // cells(k)%k // ' is not a finite number within double ' // &
                    'precision (about 1.8E+308): a table holds finite reals', &
                    file=path, line=line)
                return
            end if
            if (cells(k)%kind == V_TEXT .and. t%columns(k)%kind /= TABLE_TEXT .and. &
                .not. any(t%columns(k)%present(1:r))) call retype_text(t, k, len(cells(k)%k))
            if (cells(k)%kind == V_TEXT .and. t%columns(k)%kind == TABLE_TEXT .and. &
                len(cells(k)%k) > t%columns(k)%width .and. &
                table_text_width_for(len(cells(k)%k)) > 0) &
                t%columns(k)%width = table_text_width_for(len(cells(k)%k))
            select case (cells(k)%kind)
            case (V_INT)
                call table_set_int(t, k, r, cells(k)%i, st)
            case (V_REAL)
                call table_set_real(t, k, r, cells(k)%r, st)
            case default
                call table_set_text(t, k, r, cells(k)%k, st)
            end select
            if (st%failed()) then
                call set_error(st, STATUS_MODEL_ERROR, 'row ' // to_text(int(r, i4)) // &
                    ': ' // st%message, file=path, line=line)
                return
            end if
        end do
    end subroutine store_row

    !> A column without values yet becomes a text column.
    subroutine retype_text(t, column, length)
        type(table_t), intent(inout) :: t
        integer, intent(in) :: column, length
        if (allocated(t%columns(column)%ints)) deallocate (t%columns(column)%ints)
        if (allocated(t%columns(column)%reals)) deallocate (t%columns(column)%reals)
        allocate (t%columns(column)%texts(size(t%columns(column)%present)))
        t%columns(column)%kind = TABLE_TEXT
        t%columns(column)%width = max(TABLE_DEFAULT_TEXT_WIDTH, table_text_width_for(length))
    end subroutine retype_text

    !> A value as Code_Aster's convert: an integer, else a real (decimal comma too), else
    !> a text; '-' is absent in TABLEAU and ASTER (`dash_absent`). `as_text`: a K column.
    subroutine parse_cell(text, dash_absent, as_text, cell)
        character(len=*), intent(in) :: text
        logical, intent(in) :: dash_absent, as_text
        type(cell_text_t), intent(out) :: cell
        integer :: ios
        character(len=:), allocatable :: number
        if (len(text) == 0 .or. (dash_absent .and. text == '-')) return
        cell%kind = V_TEXT
        cell%k = text
        if (as_text) return
        select case (to_lower(text))
        case ('nan', '+nan', '-nan', 'inf', '+inf', '-inf', 'infinity', '+infinity', &
              '-infinity')
            cell%kind = V_OVERFLOW               ! Python reads them as floats: refused
            return
        end select
        if (is_integer_text(text)) then
            read (text, *, iostat=ios) cell%i
            if (ios == 0) then
                cell%kind = V_INT
                return
            end if
        end if
        number = text
        if (index(number, ',') > 0 .and. index(number, '.') == 0) &
            number(index(number, ','):index(number, ',')) = '.'
        if (is_real_text(number)) then
            call read_real(number, cell%r, ios)
            if (ios == 0) then
                cell%kind = V_REAL
            else if (ios == 1) then
                cell%kind = V_OVERFLOW          ! beyond double precision: an error
            end if
        end if
    end subroutine parse_cell

    !> Reads a real with the overflow trap off: a decimal beyond double precision is
    !> reported (ios = 1), never a floating-point exception (values below the smallest
    !> double read as 0, as Python's float()).
    subroutine read_real(text, value, ios)
        character(len=*), intent(in) :: text
        real(dp), intent(out) :: value
        integer, intent(out) :: ios
        logical :: halting
        call ieee_get_halting_mode(ieee_overflow, halting)
        call ieee_set_halting_mode(ieee_overflow, .false.)
        read (text, *, iostat=ios) value
        call ieee_set_halting_mode(ieee_overflow, halting)
        if (ios /= 0) then
            ios = 2
            value = 0.0_dp
        else if (.not. ieee_is_finite(value)) then
            ios = 1
            value = 0.0_dp
        end if
    end subroutine read_real

    !> [+-]digits
    pure logical function is_integer_text(text)
        character(len=*), intent(in) :: text
        integer :: start
        start = 1
        if (len(text) > 0) then
            if (text(1:1) == '+' .or. text(1:1) == '-') start = 2
        end if
        is_integer_text = len(text) >= start .and. len(text) - start < 19 .and. &
            verify(text(start:), '0123456789') == 0
    end function is_integer_text

    !> [+-](digits[.digits*] | .digits)([eEdD][+-]digits)
    pure logical function is_real_text(text)
        character(len=*), intent(in) :: text
        integer :: p, n, digits, e
        is_real_text = .false.
        n = len(text)
        p = 1
        if (n == 0) return
        if (text(1:1) == '+' .or. text(1:1) == '-') p = 2
        digits = 0
        do while (p <= n)
            if (index('0123456789', text(p:p)) == 0) exit
            p = p + 1; digits = digits + 1
        end do
        if (p <= n) then
            if (text(p:p) == '.') then
                p = p + 1
                do while (p <= n)
                    if (index('0123456789', text(p:p)) == 0) exit
                    p = p + 1; digits = digits + 1
                end do
            end if
        end if
        if (digits == 0) return
        if (p <= n) then
            if (index('eEdD', text(p:p)) == 0) return
            p = p + 1
            if (p <= n) then
                if (text(p:p) == '+' .or. text(p:p) == '-') p = p + 1
            end if
            e = 0
            do while (p <= n)
                if (index('0123456789', text(p:p)) == 0) exit
                p = p + 1; e = e + 1
            end do
            if (e == 0 .or. e > 4) return
        end if
        is_real_text = p > n
    end function is_real_text

    !> Fields split at runs of separator characters, after removing them at both ends
    !> (Code_Aster's msplit).
    function split_fields(line, separator) result(fields)
        character(len=*), intent(in) :: line, separator
        type(string_t), allocatable :: fields(:)
        character(len=:), allocatable :: text
        integer :: p, q
        allocate (fields(0))
        text = strip_chars(line, separator)
        if (separator == ' ') text = strip_chars(text, ' ' // achar(9) // achar(13))
        p = 1
        do while (p <= len(text))
            q = index(text(p:), separator)
            if (q == 0) then
                call append_string(fields, text(p:))
                exit
            end if
            call append_string(fields, text(p:p + q - 2))
            p = p + q - 1
            do while (p <= len(text))
                if (text(p:min(p + len(separator) - 1, len(text))) /= separator) exit
                p = p + len(separator)
            end do
        end do
    end function split_fields

    !> `text` without the characters of `chars` at both ends.
    pure function strip_chars(text, chars) result(out)
        character(len=*), intent(in) :: text, chars
        character(len=:), allocatable :: out
        integer :: a, b
        a = 1
        b = len(text)
        do while (a <= b)
            if (index(chars, text(a:a)) == 0) exit
            a = a + 1
        end do
        do while (b >= a)
            if (index(chars, text(b:b)) == 0) exit
            b = b - 1
        end do
        out = text(a:b)
    end function strip_chars

end module lire_table_command
