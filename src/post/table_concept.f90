!> The table concept (`table_sdaster`), as Code_Aster's tables: named columns (NOM_PARA) of
!> one type each, integers (I), reals (R) or strings of at most 8, 16, 24, 32 or 80
!> characters (K8 .. K80), rows whose cells may be absent, and a title (TITRE).
!>
!> Tables are results of commands (CREA_TABLE, CALC_TABLE, POST_RELEVE_T, ...) and inputs
!> of others (TEST_TABLE, IMPR_TABLE, RECU_FONCTION, ...). Storage is by column, each
!> column holding one array per type and a presence mask, so that building a table of
!> n rows costs O(n) and selecting rows or columns is a gather.
!>
!> A column's type follows Code_Aster's rules for mixed values (Table.append,
!> typaster): an integer put into a real column is stored as a real, a real put into an
!> integer column turns the column into a real one (the "envelope" type R); a text never
!> mixes with numbers; a text longer than the column's width is refused (Code_Aster's
!> Fortran would cut it).
module table_concept
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use kinds, only: dp, i4, i8
    use strings, only: string_t, to_text, join_words, to_upper
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use deck_concept, only: concept_t, concept_display_name
    use deck_suggest, only: did_you_mean
    implicit none
    private

    !> Column types.
    integer, parameter, public :: TABLE_INT = 1, TABLE_REAL = 2, TABLE_TEXT = 3
    !> Widths of text columns Code_Aster knows (K8, K16, K24, K32, K80).
    integer, parameter, public :: TABLE_TEXT_WIDTHS(5) = [8, 16, 24, 32, 80]
    !> Width of a text column whose width nobody chose (Code_Aster's Python tables: K24).
    integer, parameter, public :: TABLE_DEFAULT_TEXT_WIDTH = 24
    !> Most rows a table may have (bounds what a deck can make parasol allocate: 10
    !> million rows is 150 times the nodes of the 128 x 512 plate).
    integer, parameter, public :: MAX_TABLE_ROWS = 10000000
    !> The catalog type of tables.
    character(len=*), parameter, public :: TABLE_TYPE_NAME = 'table_sdaster'

    !> One column. Only the array of its type is allocated; `present(r)` says whether row
    !> r has a value. `width` is the K width of a text column (0 for numbers).
    type, public :: table_column_t
        character(len=:), allocatable :: name
        integer :: kind = TABLE_REAL
        integer :: width = 0
        integer(i8), allocatable :: ints(:)
        real(dp), allocatable :: reals(:)
        type(string_t), allocatable :: texts(:)
        logical, allocatable :: present(:)
    end type table_column_t

    !> A table. Columns 1..n_columns, rows 1..n_rows (the arrays may hold more: capacity).
    type, extends(concept_t), public :: table_t
        type(table_column_t), allocatable :: columns(:)
        integer :: n_columns = 0
        integer :: n_rows = 0
        integer :: capacity = 0
        type(string_t), allocatable :: title(:)     !< TITRE lines ('' none)
    contains
        procedure :: type_name => table_concept_type
        procedure :: summary => table_summary
    end type table_t

    public :: table_init, table_find_column, table_require_column, table_add_column, &
        table_add_rows, table_set_int, table_set_real, table_set_text, table_has_cell, &
        table_cell_real, table_cell_int, table_cell_text, table_kind_label, &
        table_select_rows, table_select_columns, table_column_names, table_rename_column, &
        table_set_value_text, table_is_number, table_text_width_for, table_copy_cell, &
        table_append_title, table_remove_empty_rows, table_replace_rows, &
        table_default_title, table_label, table_entity_label

contains

    !> The text a table's NOEUD or MAILLE cell (and POST_ELEM MINMAX's NO_/MA_ cells) holds
    !> for the mesh's node or cell `number`: the number itself ('19'), as code_aster 17's
    !> int_to_char8 writes it for a mesh without names, which every mesh LIRE_MAILLAGE
    !> makes is (lrmast drops the .mail file's names; MED files' names are not read), so
    !> that a deck's FILTRE VALE_K='19' finds the row of node N19.
    function table_entity_label(number) result(label)
        integer, intent(in) :: number
        character(len=:), allocatable :: label
        label = to_text(number)
    end function table_entity_label

    function table_concept_type(self) result(name)
        class(table_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = TABLE_TYPE_NAME
        if (.false.) name = to_text(self%n_rows)
    end function table_concept_type

    !> One line for the .mess: rows and columns with their types.
    function table_summary(self) result(text)
        class(table_t), intent(in) :: self
        character(len=:), allocatable :: text
        integer :: c
        text = concept_display_name(self) // ' (' // TABLE_TYPE_NAME // ') with ' // &
            to_text(int(self%n_rows, i4)) // ' rows, columns'
        do c = 1, self%n_columns
            text = text // ' ' // shown_name(self%columns(c)%name) // '(' // &
                table_kind_label(self%columns(c)) // ')'
        end do
        if (self%n_columns == 0) text = text // ' (none)'
    end function table_summary

    !> A column name as the .mess shows it: quoted unless it is an identifier (a name read
    !> from a file may be '1,5' or 'inf': quoted, it cannot pass for a number).
    pure function shown_name(name) result(text)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: text
        logical :: plain
        plain = len(name) > 0
        if (plain) plain = verify(name(1:1), 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz') &
            == 0 .and. verify(name, 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz' // &
            '0123456789_') == 0 .and. to_upper(name) /= 'INF' .and. to_upper(name) /= 'NAN' &
            .and. to_upper(name) /= 'INFINITY'
        text = name
        if (.not. plain) text = '''' // name // ''''
    end function shown_name

    !> The title of a table that has none, as Code_Aster's default title (titre.F90: 'ASTER
    !> <version> CONCEPT <name> CALCULE LE <date> A <time> DE TYPE TABLE_SDASTER') without
    !> the version, date and time, so that listings are deterministic.
    function table_default_title(t) result(text)
        type(table_t), intent(in) :: t
        character(len=:), allocatable :: text
        text = 'CONCEPT ' // concept_display_name(t) // ' CALCULE DE TYPE TABLE_SDASTER'
    end function table_default_title

    !> 'table NAME' in messages, 'the table' while it has no name (being built).
    function table_label(t) result(text)
        type(table_t), intent(in) :: t
        character(len=:), allocatable :: text
        text = 'the table'
        if (allocated(t%name)) then
            if (len(t%name) > 0) text = 'table ' // t%name
        end if
    end function table_label

    !> Empties a table (no columns, no rows, no title).
    subroutine table_init(t)
        type(table_t), intent(inout) :: t
        if (allocated(t%columns)) deallocate (t%columns)
        allocate (t%columns(4))
        t%n_columns = 0
        t%n_rows = 0
        t%capacity = 0
        if (allocated(t%title)) deallocate (t%title)
        allocate (t%title(0))
    end subroutine table_init

    !> The Code_Aster type of a column: I, R, K8, K16, ...
    pure function table_kind_label(col) result(label)
        type(table_column_t), intent(in) :: col
        character(len=:), allocatable :: label
        select case (col%kind)
        case (TABLE_INT)
            label = 'I'
        case (TABLE_REAL)
            label = 'R'
        case default
            label = 'K' // to_text(int(col%width, i4))
        end select
    end function table_kind_label

    !> True for a numeric column (I or R).
    pure logical function table_is_number(col)
        type(table_column_t), intent(in) :: col
        table_is_number = col%kind == TABLE_INT .or. col%kind == TABLE_REAL
    end function table_is_number

    !> The K width (8, 16, 24, 32, 80) that holds a text of `length` characters, 0 when
    !> none does.
    pure integer function table_text_width_for(length)
        integer, intent(in) :: length
        integer :: k
        table_text_width_for = 0
        do k = 1, size(TABLE_TEXT_WIDTHS)
            if (length <= TABLE_TEXT_WIDTHS(k)) then
                table_text_width_for = TABLE_TEXT_WIDTHS(k)
                return
            end if
        end do
    end function table_text_width_for

    !> Index of column `name` (exact, case-sensitive as Code_Aster), 0 when absent.
    pure integer function table_find_column(t, name)
        type(table_t), intent(in) :: t
        character(len=*), intent(in) :: name
        integer :: c
        table_find_column = 0
        do c = 1, t%n_columns
            if (t%columns(c)%name == name) then
                table_find_column = c
                return
            end if
        end do
    end function table_find_column

    !> The column names, in order.
    function table_column_names(t) result(names)
        type(table_t), intent(in) :: t
        type(string_t), allocatable :: names(:)
        integer :: c
        allocate (names(t%n_columns))
        do c = 1, t%n_columns
            names(c)%s = t%columns(c)%name
        end do
    end function table_column_names

    !> Index of column `name`, or an error naming the table's columns (issue 20 §8: a
    !> column that does not exist says which do), with a did-you-mean.
    !>  st : STATUS_MODEL_ERROR when absent
    subroutine table_require_column(t, name, column, st)
        type(table_t), intent(in) :: t
        character(len=*), intent(in) :: name
        integer, intent(out) :: column
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: names(:)
        column = table_find_column(t, name)
        if (column > 0) return
        names = table_column_names(t)
        if (size(names) == 0) then
            call set_error(st, STATUS_MODEL_ERROR, table_label(t) // &
                ' has no column ' // name // ' (it has no columns)')
        else
            call set_error(st, STATUS_MODEL_ERROR, table_label(t) // &
                ' has no column ' // name // did_you_mean(name, names) // '; its columns: ' // &
                join_words(names, ', '))
        end if
    end subroutine table_require_column

    !> Adds an empty column (every cell absent).
    !>  kind  : TABLE_INT, TABLE_REAL or TABLE_TEXT;  width : K width of a text column
    !>  column : out, its index
    !>  st : STATUS_MODEL_ERROR when a column of that name exists (Code_Aster: the names of
    !>       the parameters must differ)
    subroutine table_add_column(t, name, kind, column, st, width)
        type(table_t), intent(inout) :: t
        character(len=*), intent(in) :: name
        integer, intent(in) :: kind
        integer, intent(out) :: column
        type(status_t), intent(inout) :: st
        integer, intent(in), optional :: width
        type(table_column_t), allocatable :: bigger(:)
        integer :: c
        column = 0
        if (table_find_column(t, name) > 0) then
            call set_error(st, STATUS_MODEL_ERROR, table_label(t) // &
                ' already has a column ' // name // ' (column names must differ)')
            return
        end if
        if (.not. allocated(t%columns)) allocate (t%columns(4))
        if (t%n_columns == size(t%columns)) then
            allocate (bigger(2 * size(t%columns)))
            do c = 1, t%n_columns
                call move_column(t%columns(c), bigger(c))
            end do
            call move_alloc(bigger, t%columns)
        end if
        t%n_columns = t%n_columns + 1
        column = t%n_columns
        associate (col => t%columns(column))
            col%name = name
            col%kind = kind
            col%width = 0
            if (kind == TABLE_TEXT) then
                col%width = TABLE_DEFAULT_TEXT_WIDTH
                if (present(width)) col%width = width
            end if
            call allocate_storage(col, t%capacity)
        end associate
    end subroutine table_add_column

    !> Moves a column's storage (no copy of the cells).
    subroutine move_column(from, to)
        type(table_column_t), intent(inout) :: from
        type(table_column_t), intent(inout) :: to
        call move_alloc(from%name, to%name)
        to%kind = from%kind
        to%width = from%width
        if (allocated(from%ints)) call move_alloc(from%ints, to%ints)
        if (allocated(from%reals)) call move_alloc(from%reals, to%reals)
        if (allocated(from%texts)) call move_alloc(from%texts, to%texts)
        call move_alloc(from%present, to%present)
    end subroutine move_column

    subroutine allocate_storage(col, capacity)
        type(table_column_t), intent(inout) :: col
        integer, intent(in) :: capacity
        if (allocated(col%ints)) deallocate (col%ints)
        if (allocated(col%reals)) deallocate (col%reals)
        if (allocated(col%texts)) deallocate (col%texts)
        select case (col%kind)
        case (TABLE_INT)
            allocate (col%ints(capacity), source=0_i8)
        case (TABLE_REAL)
            allocate (col%reals(capacity), source=0.0_dp)
        case default
            allocate (col%texts(capacity))
        end select
        if (allocated(col%present)) deallocate (col%present)
        allocate (col%present(capacity), source=.false.)
    end subroutine allocate_storage

    !> Appends `n` rows whose cells are all absent (capacity doubles: O(1) amortised).
    subroutine table_add_rows(t, n)
        type(table_t), intent(inout) :: t
        integer, intent(in) :: n
        integer :: c, new_capacity
        if (n <= 0) return
        if (t%n_rows + n > t%capacity) then
            new_capacity = max(t%n_rows + n, 2 * t%capacity, 16)
            do c = 1, t%n_columns
                call grow_column(t%columns(c), t%n_rows, new_capacity)
            end do
            t%capacity = new_capacity
        end if
        do c = 1, t%n_columns
            t%columns(c)%present(t%n_rows + 1:t%n_rows + n) = .false.
        end do
        t%n_rows = t%n_rows + n
    end subroutine table_add_rows

    subroutine grow_column(col, used, capacity)
        type(table_column_t), intent(inout) :: col
        integer, intent(in) :: used, capacity
        integer(i8), allocatable :: ints(:)
        real(dp), allocatable :: reals(:)
        type(string_t), allocatable :: texts(:)
        logical, allocatable :: present(:)
        integer :: r
        allocate (present(capacity), source=.false.)
        present(1:used) = col%present(1:used)
        call move_alloc(present, col%present)
        select case (col%kind)
        case (TABLE_INT)
            allocate (ints(capacity), source=0_i8)
            ints(1:used) = col%ints(1:used)
            call move_alloc(ints, col%ints)
        case (TABLE_REAL)
            allocate (reals(capacity), source=0.0_dp)
            reals(1:used) = col%reals(1:used)
            call move_alloc(reals, col%reals)
        case default
            allocate (texts(capacity))
            do r = 1, used
                if (allocated(col%texts(r)%s)) call move_alloc(col%texts(r)%s, texts(r)%s)
            end do
            call move_alloc(texts, col%texts)
        end select
    end subroutine grow_column

    !> Sets cell (row, column) to an integer. A real column stores it as a real.
    !>  st : STATUS_MODEL_ERROR for a text column (types do not mix)
    subroutine table_set_int(t, column, row, value, st)
        type(table_t), intent(inout) :: t
        integer, intent(in) :: column, row
        integer(i8), intent(in) :: value
        type(status_t), intent(inout) :: st
        associate (col => t%columns(column))
            select case (col%kind)
            case (TABLE_INT)
                col%ints(row) = value
            case (TABLE_REAL)
                col%reals(row) = real(value, dp)
            case default
                call mixed_types(t, col, 'the integer ' // to_text(value), st)
                return
            end select
            col%present(row) = .true.
        end associate
    end subroutine table_set_int

    !> Sets cell (row, column) to a real; an integer column becomes a real one.
    !>  st : STATUS_MODEL_ERROR for a text column, or a value that is not a finite number
    !>       (a table never holds NaN or Inf: its listing could not be read back)
    subroutine table_set_real(t, column, row, value, st)
        type(table_t), intent(inout) :: t
        integer, intent(in) :: column, row
        real(dp), intent(in) :: value
        type(status_t), intent(inout) :: st
        if (.not. ieee_is_finite(value)) then
            call set_error(st, STATUS_MODEL_ERROR, 'column ' // t%columns(column)%name // &
                ', row ' // to_text(int(row, i4)) // ': the value is not a finite number')
            return
        end if
        associate (col => t%columns(column))
            select case (col%kind)
            case (TABLE_INT)
                call promote_to_real(col, t%capacity)
                col%reals(row) = value
            case (TABLE_REAL)
                col%reals(row) = value
            case default
                call mixed_types(t, col, 'the real ' // to_text(value), st)
                return
            end select
            col%present(row) = .true.
        end associate
    end subroutine table_set_real

    !> Sets cell (row, column) to a text.
    !>  st : STATUS_MODEL_ERROR for a numeric column, or a text longer than the column's K
    !>       width
    subroutine table_set_text(t, column, row, value, st)
        type(table_t), intent(inout) :: t
        integer, intent(in) :: column, row
        character(len=*), intent(in) :: value
        type(status_t), intent(inout) :: st
        associate (col => t%columns(column))
            if (col%kind /= TABLE_TEXT) then
                call mixed_types(t, col, 'the text ''' // value // '''', st)
                return
            end if
            if (len_trim(value) > col%width) then
                call set_error(st, STATUS_MODEL_ERROR, 'column ' // col%name // ' holds ' // &
                    'texts of at most ' // to_text(int(col%width, i4)) // ' characters (K' // &
                    to_text(int(col%width, i4)) // '); ''' // trim(value) // ''' has ' // &
                    to_text(int(len_trim(value), i4)))
                return
            end if
            col%texts(row)%s = trim(value)
            col%present(row) = .true.
        end associate
    end subroutine table_set_text

    subroutine mixed_types(t, col, what, st)
        type(table_t), intent(in) :: t
        type(table_column_t), intent(in) :: col
        character(len=*), intent(in) :: what
        type(status_t), intent(inout) :: st
        call set_error(st, STATUS_MODEL_ERROR, 'column ' // col%name // ' of ' // &
            table_label(t) // ' holds values of type ' // table_kind_label(col) // &
            ': ' // what // ' cannot go in it')
    end subroutine mixed_types

    !> An integer column becomes a real one (Code_Aster's envelope type of I and R).
    subroutine promote_to_real(col, capacity)
        type(table_column_t), intent(inout) :: col
        integer, intent(in) :: capacity
        real(dp), allocatable :: reals(:)
        allocate (reals(capacity))
        reals = real(col%ints, dp)
        deallocate (col%ints)
        call move_alloc(reals, col%reals)
        col%kind = TABLE_REAL
    end subroutine promote_to_real

    !> Sets a cell from its text as written in a table file: an integer, a real or a
    !> text, according to the column's type ('-' = absent is the caller's business).
    !>  st : STATUS_MODEL_ERROR when the text is not a number of the column's type
    subroutine table_set_value_text(t, column, row, text, st)
        type(table_t), intent(inout) :: t
        integer, intent(in) :: column, row
        character(len=*), intent(in) :: text
        type(status_t), intent(inout) :: st
        integer(i8) :: i
        real(dp) :: x
        integer :: ios
        select case (t%columns(column)%kind)
        case (TABLE_INT)
            read (text, *, iostat=ios) i
            if (ios /= 0 .or. index(text, '.') > 0 .or. scan(text, 'eEdD') > 0) then
                call set_error(st, STATUS_MODEL_ERROR, 'column ' // t%columns(column)%name // &
                    ' holds integers: ''' // trim(text) // ''' is not one')
                return
            end if
            call table_set_int(t, column, row, i, st)
        case (TABLE_REAL)
            read (text, *, iostat=ios) x
            if (ios /= 0) then
                call set_error(st, STATUS_MODEL_ERROR, 'column ' // t%columns(column)%name // &
                    ' holds reals: ''' // trim(text) // ''' is not one')
                return
            end if
            call table_set_real(t, column, row, x, st)
        case default
            call table_set_text(t, column, row, text, st)
        end select
    end subroutine table_set_value_text

    !> True when cell (row, column) holds a value.
    pure logical function table_has_cell(t, column, row)
        type(table_t), intent(in) :: t
        integer, intent(in) :: column, row
        table_has_cell = t%columns(column)%present(row)
    end function table_has_cell

    !> The value of a numeric cell as a real (0 for an absent or text cell).
    pure real(dp) function table_cell_real(t, column, row)
        type(table_t), intent(in) :: t
        integer, intent(in) :: column, row
        table_cell_real = 0.0_dp
        if (.not. t%columns(column)%present(row)) return
        select case (t%columns(column)%kind)
        case (TABLE_INT)
            table_cell_real = real(t%columns(column)%ints(row), dp)
        case (TABLE_REAL)
            table_cell_real = t%columns(column)%reals(row)
        end select
    end function table_cell_real

    !> The value of an integer cell (0 for an absent or other cell).
    pure integer(i8) function table_cell_int(t, column, row)
        type(table_t), intent(in) :: t
        integer, intent(in) :: column, row
        table_cell_int = 0
        if (.not. t%columns(column)%present(row)) return
        if (t%columns(column)%kind == TABLE_INT) table_cell_int = t%columns(column)%ints(row)
    end function table_cell_int

    !> The text of a text cell ('' for an absent or numeric cell).
    pure function table_cell_text(t, column, row) result(text)
        type(table_t), intent(in) :: t
        integer, intent(in) :: column, row
        character(len=:), allocatable :: text
        text = ''
        if (.not. t%columns(column)%present(row)) return
        if (t%columns(column)%kind == TABLE_TEXT) text = t%columns(column)%texts(row)%s
    end function table_cell_text

    !> Copies cell (row_from, column_from) of `from` into (row_to, column_to) of `t` (an
    !> absent cell stays absent). Types follow table_set_*.
    subroutine table_copy_cell(from, column_from, row_from, t, column_to, row_to, st)
        type(table_t), intent(in) :: from
        integer, intent(in) :: column_from, row_from, column_to, row_to
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        associate (col => from%columns(column_from))
            if (.not. col%present(row_from)) then
                t%columns(column_to)%present(row_to) = .false.
                return
            end if
            select case (col%kind)
            case (TABLE_INT)
                call table_set_int(t, column_to, row_to, col%ints(row_from), st)
            case (TABLE_REAL)
                call table_set_real(t, column_to, row_to, col%reals(row_from), st)
            case default
                call table_set_text(t, column_to, row_to, col%texts(row_from)%s, st)
            end select
        end associate
    end subroutine table_copy_cell

    !> The table made of rows `rows` of `t` (in that order, repeats allowed), every column
    !> kept, title kept.
    function table_select_rows(t, rows) result(out)
        type(table_t), intent(in) :: t
        integer, intent(in) :: rows(:)
        type(table_t) :: out
        integer :: c, k
        call table_init(out)
        out%title = t%title
        deallocate (out%columns)
        allocate (out%columns(max(4, t%n_columns)))
        out%n_columns = t%n_columns
        out%n_rows = size(rows)
        out%capacity = size(rows)
        do c = 1, t%n_columns
            associate (src => t%columns(c), dst => out%columns(c))
                dst%name = src%name
                dst%kind = src%kind
                dst%width = src%width
                dst%present = src%present(rows)
                select case (src%kind)
                case (TABLE_INT)
                    dst%ints = src%ints(rows)
                case (TABLE_REAL)
                    dst%reals = src%reals(rows)
                case default
                    allocate (dst%texts(size(rows)))
                    do k = 1, size(rows)
                        if (src%present(rows(k))) dst%texts(k)%s = src%texts(rows(k))%s
                    end do
                end select
            end associate
        end do
    end function table_select_rows

    !> The table made of columns `columns` of `t` (in that order), every row kept.
    function table_select_columns(t, columns) result(out)
        type(table_t), intent(in) :: t
        integer, intent(in) :: columns(:)
        type(table_t) :: out
        integer :: c
        call table_init(out)
        out%title = t%title
        deallocate (out%columns)
        allocate (out%columns(max(4, size(columns))))
        out%n_columns = size(columns)
        out%n_rows = t%n_rows
        out%capacity = t%n_rows
        do c = 1, size(columns)
            associate (src => t%columns(columns(c)), dst => out%columns(c))
                dst%name = src%name
                dst%kind = src%kind
                dst%width = src%width
                dst%present = src%present(1:t%n_rows)
                select case (src%kind)
                case (TABLE_INT)
                    dst%ints = src%ints(1:t%n_rows)
                case (TABLE_REAL)
                    dst%reals = src%reals(1:t%n_rows)
                case default
                    dst%texts = src%texts(1:t%n_rows)
                end select
            end associate
        end do
    end function table_select_columns

    !> Keeps rows `rows` of `t` only (in that order), its name and title unchanged.
    subroutine table_replace_rows(t, rows)
        type(table_t), intent(inout) :: t
        integer, intent(in) :: rows(:)
        type(table_t) :: kept
        character(len=:), allocatable :: name
        kept = table_select_rows(t, rows)
        if (allocated(t%name)) call move_alloc(t%name, name)
        call move_alloc(kept%columns, t%columns)
        t%n_rows = kept%n_rows
        t%capacity = kept%capacity
        if (allocated(name)) call move_alloc(name, t%name)
    end subroutine table_replace_rows

    !> Renames column `old` to `new`.
    !>  st : STATUS_MODEL_ERROR when `old` does not exist (naming the columns) or `new`
    !>       does
    subroutine table_rename_column(t, old, new, st)
        type(table_t), intent(inout) :: t
        character(len=*), intent(in) :: old, new
        type(status_t), intent(inout) :: st
        integer :: c
        call table_require_column(t, old, c, st)
        if (st%failed()) return
        if (old == new) return
        if (table_find_column(t, new) > 0) then
            call set_error(st, STATUS_MODEL_ERROR, table_label(t) // &
                ' already has a column ' // new // ': ' // old // ' cannot take its name')
            return
        end if
        t%columns(c)%name = new
    end subroutine table_rename_column

    !> Adds title lines (each line of `text` split at new lines).
    subroutine table_append_title(t, text)
        type(table_t), intent(inout) :: t
        character(len=*), intent(in) :: text
        type(string_t), allocatable :: bigger(:)
        integer :: start, k, n, i
        if (.not. allocated(t%title)) allocate (t%title(0))
        start = 1
        do k = 1, len(text) + 1
            if (k <= len(text)) then
                if (text(k:k) /= new_line('a')) cycle
            end if
            n = size(t%title)
            allocate (bigger(n + 1))
            do i = 1, n
                call move_alloc(t%title(i)%s, bigger(i)%s)
            end do
            bigger(n + 1)%s = text(start:k - 1)
            call move_alloc(bigger, t%title)
            start = k + 1
        end do
    end subroutine table_append_title

    !> Removes the rows whose cells are all absent (Code_Aster's tables never keep them).
    subroutine table_remove_empty_rows(t)
        type(table_t), intent(inout) :: t
        integer, allocatable :: keep(:)
        logical, allocatable :: used(:)
        integer :: c, r
        allocate (used(t%n_rows), source=.false.)
        do c = 1, t%n_columns
            used = used .or. t%columns(c)%present(1:t%n_rows)
        end do
        if (all(used)) return
        keep = pack([(r, r=1, t%n_rows)], used)
        call table_replace_rows(t, keep)
    end subroutine table_remove_empty_rows

end module table_concept
