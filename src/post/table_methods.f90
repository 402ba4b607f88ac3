!> The Python side of tables (doc/tables.md, "From the deck language"), as Code_Aster's
!> objects give it (code_aster/ObjectsExt/table_ext.py, code_aster/Objects/table_py.py),
!> through the concept-method registry (doc/architecture.md, "Concept methods"):
!>  table_sdaster  TAB['PARA', ROW] (ROW from 1; a column or row the table lacks is an
!>                 error), TAB.EXTR_TABLE(para=None) (a Table), TAB.TITRE(), TAB.get_nrow(),
!>                 len(TAB);
!>  Table          tab.PARA (a Colonne), tab.para (the names), tab.rows (a list of dicts,
!>                 the cells a row has), tab.values() (a dict of lists, None for an absent
!>                 cell), tab.titr, tab['A'] / tab['A', 'B'] (a Table of those columns),
!>                 len(tab);
!>  Colonne        col[i] (from 0, negative from the end), len(col), col.values(),
!>                 col.not_none_values(), and the filters that give a Table of the rows
!>                 whose cell passes: col == v, col != v (texts compared without their
!>                 surrounding blanks, numbers exactly; v may be a list: any of them),
!>                 col < v, col <= v (v a list: its largest), col > v, col >= v (its
!>                 smallest), col.MAXI(), col.MINI(), col.MAXI_ABS(), col.MINI_ABS(),
!>                 col.VIDE(), col.NON_VIDE().
!> A cell is an integer, a real, a text or None. A Table and a Colonne are copies of the
!> rows they were made from: a later change of the table does not reach them, as in Python.
module table_methods
    use kinds, only: dp, i4, i8
    use strings, only: string_t, to_text
    use status, only: status_t, set_error, clear_status, STATUS_DECK_ERROR
    use deck_value, only: value_t, value_list_t, VK_NONE, VK_INT, VK_REAL, VK_BOOL, VK_STR, &
        VK_TUPLE, VK_LIST, VK_FACTOR, int_value, real_value, str_value, nitems, item, &
        pack_values, sequence_value, value_text, kind_label, append_value
    use deck_concept, only: concept_t
    use run_context, only: run_context_t, method_call_t
    use table_concept, only: table_t, table_init, table_find_column, table_select_rows, &
        table_select_columns, table_column_names, TABLE_INT, TABLE_REAL, TABLE_TEXT, &
        table_label
    implicit none
    private

    !> Code_Aster's Python table (table_py.Table): a copy of a table's rows.
    type, extends(table_t), public :: py_table_t
    contains
        procedure :: type_name => py_table_type
    end type py_table_t

    !> A column of a Python table (table_py.Colonne): its table and the column's name
    !> (column 0 when the table has no such column: every cell None, as Code_Aster's).
    type, extends(table_t), public :: py_column_t
        character(len=:), allocatable :: column_name
    contains
        procedure :: type_name => py_column_type
    end type py_column_t

    public :: register_table_methods

contains

    function py_table_type(self) result(name)
        class(py_table_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'Table'
        if (.false.) name = to_text(int(self%n_rows, i4))
    end function py_table_type

    function py_column_type(self) result(name)
        class(py_column_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'Colonne'
        if (.false.) name = self%column_name
    end function py_column_type

    !> The methods of table_sdaster, Table and Colonne.
    subroutine register_table_methods(ctx)
        type(run_context_t), intent(inout) :: ctx
        call ctx%register_method('table_sdaster', 'EXTR_TABLE', sd_extr_table)
        call ctx%register_method('table_sdaster', '__getitem__', sd_cell)
        call ctx%register_method('table_sdaster', 'TITRE', sd_title)
        call ctx%register_method('table_sdaster', 'get_nrow', sd_length)
        call ctx%register_method('table_sdaster', '__len__', sd_length)
        call ctx%register_method('Table', '*', py_attribute)
        call ctx%register_method('Table', 'values', py_values)
        call ctx%register_method('Table', '__getitem__', py_columns)
        call ctx%register_method('Table', '__len__', sd_length)
        call ctx%register_method('Colonne', '__getitem__', column_item)
        call ctx%register_method('Colonne', '__len__', sd_length)
        call ctx%register_method('Colonne', 'values', column_values)
        call ctx%register_method('Colonne', 'not_none_values', column_values)
        call ctx%register_method('Colonne', '__eq__', column_filter)
        call ctx%register_method('Colonne', '__ne__', column_filter)
        call ctx%register_method('Colonne', '__lt__', column_filter)
        call ctx%register_method('Colonne', '__le__', column_filter)
        call ctx%register_method('Colonne', '__gt__', column_filter)
        call ctx%register_method('Colonne', '__ge__', column_filter)
        call ctx%register_method('Colonne', 'MAXI', column_filter)
        call ctx%register_method('Colonne', 'MINI', column_filter)
        call ctx%register_method('Colonne', 'MAXI_ABS', column_filter)
        call ctx%register_method('Colonne', 'MINI_ABS', column_filter)
        call ctx%register_method('Colonne', 'VIDE', column_filter)
        call ctx%register_method('Colonne', 'NON_VIDE', column_filter)
    end subroutine register_table_methods

    ! ---- helpers ----------------------------------------------------------------------------

    !> A handler's start: false in the check pass (nothing to do) or when `obj` is not a
    !> table (st says so); else `t` is its table.
    logical function begin(ctx, obj, t, st)
        type(run_context_t), intent(in) :: ctx
        class(concept_t), pointer, intent(in) :: obj
        class(table_t), pointer, intent(out) :: t
        type(status_t), intent(out) :: st
        t => null()
        begin = .false.
        if (ctx%checking) return
        call table_of(obj, t, st)
        begin = st%ok()
    end function begin

    !> The table behind any of the three concepts.
    subroutine table_of(obj, t, st)
        class(concept_t), pointer, intent(in) :: obj
        class(table_t), pointer, intent(out) :: t
        type(status_t), intent(out) :: st
        t => null()
        select type (obj)
        class is (table_t)
            t => obj
        class default
            call set_error(st, STATUS_DECK_ERROR, 'not a table')
        end select
    end subroutine table_of

    !> Cell (column c, row r) as a deck value: an integer, a real, a text, or None.
    function cell_value(t, c, r) result(v)
        class(table_t), intent(in) :: t
        integer, intent(in) :: c, r
        type(value_t) :: v
        v%kind = VK_NONE
        if (c < 1) return
        associate (col => t%columns(c))
            if (.not. col%present(r)) return
            select case (col%kind)
            case (TABLE_INT)
                v = int_value(col%ints(r))
            case (TABLE_REAL)
                v = real_value(col%reals(r))
            case default
                v = str_value(col%texts(r)%s)
            end select
        end associate
    end function cell_value

    !> A copy of rows `rows` of `t` as a new Table concept, handed to the deck.
    subroutine new_table(ctx, t, rows, result, st)
        type(run_context_t), intent(inout) :: ctx
        class(table_t), intent(in) :: t
        integer, intent(in) :: rows(:)
        type(value_t), intent(out) :: result
        type(status_t), intent(out) :: st
        type(py_table_t), allocatable :: py
        class(concept_t), allocatable :: made
        allocate (py)
        py%table_t = table_select_rows(t, rows)
        if (allocated(t%title)) py%title = t%title
        py%name = ''
        call move_alloc(py, made)
        call ctx%concept_value(made, result, st)
    end subroutine new_table

    !> Refuses arguments for an attribute or a method that takes none.
    logical function takes_nothing(call, st)
        type(method_call_t), intent(in) :: call
        type(status_t), intent(inout) :: st
        takes_nothing = size(call%args) == 0 .and. nitems(call%kwargs) == 0
        if (.not. takes_nothing) call set_error(st, STATUS_DECK_ERROR, call%name // &
            ' takes no argument')
    end function takes_nothing

    ! ---- table_sdaster ----------------------------------------------------------------------

    !> TAB.EXTR_TABLE(para=None): a Table of the table's rows (para: of those columns).
    subroutine sd_extr_table(ctx, obj, call, result, st)
        type(run_context_t), intent(inout) :: ctx
        class(concept_t), pointer, intent(in) :: obj
        type(method_call_t), intent(in) :: call
        type(value_t), intent(out) :: result
        type(status_t), intent(out) :: st
        class(table_t), pointer :: t
        type(table_t) :: part
        integer, allocatable :: columns(:)
        integer :: k
        if (.not. begin(ctx, obj, t, st)) return
        if (.not. call%called) then
            call set_error(st, STATUS_DECK_ERROR, 'EXTR_TABLE is a method: TAB.EXTR_TABLE()')
            return
        end if
        if (size(call%args) > 1 .or. nitems(call%kwargs) > 0) then
            call set_error(st, STATUS_DECK_ERROR, 'EXTR_TABLE takes at most the list of ' // &
                'columns to keep')
            return
        end if
        if (size(call%args) == 1) then
            call column_list(t, call%args(1), columns, st)
            if (st%failed()) return
            part = table_select_columns(t, columns)
            call new_table(ctx, part, [(k, k=1, part%n_rows)], result, st)
        else
            call new_table(ctx, t, [(k, k=1, t%n_rows)], result, st)
        end if
    end subroutine sd_extr_table

    !> The columns named by a text or a sequence of texts.
    subroutine column_list(t, names, columns, st)
        class(table_t), intent(in) :: t
        type(value_t), intent(in) :: names
        integer, allocatable, intent(out) :: columns(:)
        type(status_t), intent(inout) :: st
        type(value_t) :: one
        integer :: k, c
        allocate (columns(0))
        if (names%kind == VK_STR) then
            c = table_find_column(t, names%s)
            if (c == 0) then
                call no_column(t, names%s, st)
                return
            end if
            columns = [c]
            return
        end if
        if (names%kind /= VK_TUPLE .and. names%kind /= VK_LIST) then
            call set_error(st, STATUS_DECK_ERROR, 'give column names (texts), not ' // &
                kind_label(names))
            return
        end if
        do k = 1, nitems(names)
            one = item(names, k)
            if (one%kind /= VK_STR) then
                call set_error(st, STATUS_DECK_ERROR, 'give column names (texts), not ' // &
                    kind_label(one))
                return
            end if
            c = table_find_column(t, one%s)
            if (c == 0) then
                call no_column(t, one%s, st)
                return
            end if
            columns = [columns, c]
        end do
    end subroutine column_list

    subroutine no_column(t, name, st)
        class(table_t), intent(in) :: t
        character(len=*), intent(in) :: name
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: names(:)
        character(len=:), allocatable :: list
        integer :: k
        names = table_column_names(t)
        list = ''
        do k = 1, size(names)
            if (k > 1) list = list // ', '
            list = list // names(k)%s
        end do
        call set_error(st, STATUS_DECK_ERROR, table_label(t) // ' has no column ' // &
            name // ' (its columns: ' // list // ')')
    end subroutine no_column

    !> TAB['PARA', ROW]: the cell (ROW from 1), as Code_Aster's table_ext.
    subroutine sd_cell(ctx, obj, call, result, st)
        type(run_context_t), intent(inout) :: ctx
        class(concept_t), pointer, intent(in) :: obj
        type(method_call_t), intent(in) :: call
        type(value_t), intent(out) :: result
        type(status_t), intent(out) :: st
        class(table_t), pointer :: t
        type(value_t) :: para, row
        integer :: c
        if (.not. begin(ctx, obj, t, st)) return
        if (size(call%args) /= 1) then
            call set_error(st, STATUS_DECK_ERROR, 'a cell is TAB[''PARA'', ROW]')
            return
        end if
        if (nitems(call%args(1)) /= 2 .or. call%args(1)%kind /= VK_TUPLE) then
            call set_error(st, STATUS_DECK_ERROR, 'a cell is TAB[''PARA'', ROW] (two ' // &
                'indices: the column''s name and the row from 1), not TAB[' // &
                value_text(call%args(1)) // ']')
            return
        end if
        para = item(call%args(1), 1)
        row = item(call%args(1), 2)
        if (para%kind /= VK_STR .or. row%kind /= VK_INT) then
            call set_error(st, STATUS_DECK_ERROR, 'a cell is TAB[''PARA'', ROW]: a text ' // &
                'and an integer, not TAB[' // value_text(call%args(1)) // ']')
            return
        end if
        c = table_find_column(t, para%s)
        if (c == 0) then
            call no_column(t, para%s, st)
            return
        end if
        if (row%i < 1 .or. row%i > t%n_rows) then
            call set_error(st, STATUS_DECK_ERROR, table_label(t) // ' has ' // &
                to_text(int(t%n_rows, i4)) // ' rows: no row ' // to_text(row%i) // &
                ' (rows count from 1)')
            return
        end if
        result = cell_value(t, c, int(row%i))
    end subroutine sd_cell

    !> TAB.TITRE(): the title (its lines joined by new lines).
    subroutine sd_title(ctx, obj, call, result, st)
        type(run_context_t), intent(inout) :: ctx
        class(concept_t), pointer, intent(in) :: obj
        type(method_call_t), intent(in) :: call
        type(value_t), intent(out) :: result
        type(status_t), intent(out) :: st
        class(table_t), pointer :: t
        if (.not. begin(ctx, obj, t, st)) return
        if (.not. takes_nothing(call, st)) return
        result = str_value(title_text(t))
    end subroutine sd_title

    !> The title's lines joined by new lines.
    function title_text(t) result(text)
        class(table_t), intent(in) :: t
        character(len=:), allocatable :: text
        integer :: k
        text = ''
        if (.not. allocated(t%title)) return
        do k = 1, size(t%title)
            if (k > 1) text = text // new_line('a')
            text = text // t%title(k)%s
        end do
    end function title_text

    !> len(TAB), TAB.get_nrow(), len(tab), len(col): the number of rows.
    subroutine sd_length(ctx, obj, call, result, st)
        type(run_context_t), intent(inout) :: ctx
        class(concept_t), pointer, intent(in) :: obj
        type(method_call_t), intent(in) :: call
        type(value_t), intent(out) :: result
        type(status_t), intent(out) :: st
        class(table_t), pointer :: t
        if (.not. begin(ctx, obj, t, st)) return
        if (.not. takes_nothing(call, st)) return
        result = int_value(int(t%n_rows, i8))
    end subroutine sd_length

    ! ---- Table ------------------------------------------------------------------------------

    !> tab.para, tab.rows, tab.titr, and tab.PARA (a Colonne; an unknown name gives a
    !> column of None, as table_py's __getattr__).
    subroutine py_attribute(ctx, obj, call, result, st)
        type(run_context_t), intent(inout) :: ctx
        class(concept_t), pointer, intent(in) :: obj
        type(method_call_t), intent(in) :: call
        type(value_t), intent(out) :: result
        type(status_t), intent(out) :: st
        class(table_t), pointer :: t
        type(py_column_t), allocatable :: col
        class(concept_t), allocatable :: made
        type(value_list_t) :: list, row
        type(string_t), allocatable :: names(:)
        integer :: r, c, k
        if (.not. begin(ctx, obj, t, st)) return
        if (call%called) then
            call set_error(st, STATUS_DECK_ERROR, 'a Table has no method ' // call%name // &
                ' (tab.' // call%name // ' is its column ' // call%name // ')')
            return
        end if
        select case (call%name)
        case ('para')
            names = table_column_names(t)
            allocate (list%items(size(names)))
            do k = 1, size(names)
                list%items(k) = str_value(names(k)%s)
            end do
            result = sequence_value(VK_LIST, list%items)
        case ('titr')
            result = str_value(title_text(t))
        case ('rows')
            allocate (list%items(t%n_rows))
            do r = 1, t%n_rows
                k = count([(t%columns(c)%present(r), c=1, t%n_columns)])
                allocate (row%items(k), row%keys(k))
                allocate (row%key_line(k), row%key_col(k), source=0)
                k = 0
                do c = 1, t%n_columns
                    if (.not. t%columns(c)%present(r)) cycle
                    k = k + 1
                    row%items(k) = cell_value(t, c, r)
                    row%keys(k)%s = t%columns(c)%name
                end do
                list%items(r) = pack_values(VK_FACTOR, row)
                deallocate (row%items, row%keys, row%key_line, row%key_col)
            end do
            result = sequence_value(VK_LIST, list%items)
        case default
            allocate (col)
            col%table_t = t
            col%column_name = call%name
            col%name = ''
            call move_alloc(col, made)
            call ctx%concept_value(made, result, st)
        end select
    end subroutine py_attribute

    !> tab.values(): {para: [cells]} (None for an absent cell).
    subroutine py_values(ctx, obj, call, result, st)
        type(run_context_t), intent(inout) :: ctx
        class(concept_t), pointer, intent(in) :: obj
        type(method_call_t), intent(in) :: call
        type(value_t), intent(out) :: result
        type(status_t), intent(out) :: st
        class(table_t), pointer :: t
        type(value_list_t) :: dict
        integer :: c
        if (.not. begin(ctx, obj, t, st)) return
        if (.not. takes_nothing(call, st)) return
        allocate (dict%items(t%n_columns), dict%keys(t%n_columns))
        allocate (dict%key_line(t%n_columns), dict%key_col(t%n_columns), source=0)
        do c = 1, t%n_columns
            dict%keys(c)%s = t%columns(c)%name
            dict%items(c) = column_list_value(t, c)
        end do
        result = pack_values(VK_FACTOR, dict)
    end subroutine py_values

    !> The cells of column c as a list (None for an absent cell).
    function column_list_value(t, c) result(v)
        class(table_t), intent(in) :: t
        integer, intent(in) :: c
        type(value_t) :: v
        type(value_t), allocatable :: cells(:)
        integer :: r
        allocate (cells(t%n_rows))
        do r = 1, t%n_rows
            cells(r) = cell_value(t, c, r)
        end do
        v = sequence_value(VK_LIST, cells)
    end function column_list_value

    !> tab['A'] or tab['A', 'B']: a Table of those columns (table_py's __getitem__; a name
    !> the table lacks gives an empty Table).
    subroutine py_columns(ctx, obj, call, result, st)
        type(run_context_t), intent(inout) :: ctx
        class(concept_t), pointer, intent(in) :: obj
        type(method_call_t), intent(in) :: call
        type(value_t), intent(out) :: result
        type(status_t), intent(out) :: st
        class(table_t), pointer :: t
        type(table_t) :: part
        integer, allocatable :: columns(:)
        integer :: k
        if (.not. begin(ctx, obj, t, st)) return
        if (size(call%args) /= 1) then
            call set_error(st, STATUS_DECK_ERROR, 'give the column names: tab[''A''] or ' // &
                'tab[''A'', ''B'']')
            return
        end if
        call column_list(t, call%args(1), columns, st)
        if (st%failed()) then
            call table_init(part)                          ! a missing name: empty Table
            call clear_status(st)
            call new_table(ctx, part, [integer ::], result, st)
            return
        end if
        part = table_select_columns(t, columns)
        call new_table(ctx, part, [(k, k=1, part%n_rows)], result, st)
    end subroutine py_columns

    ! ---- Colonne ----------------------------------------------------------------------------

    !> The column's index in its table (0: no such column).
    integer function column_index(obj) result(c)
        class(concept_t), pointer, intent(in) :: obj
        c = 0
        select type (obj)
        type is (py_column_t)
            c = table_find_column(obj%table_t, obj%column_name)
        end select
    end function column_index

    !> col[i]: the i-th cell (from 0; negative from the end).
    subroutine column_item(ctx, obj, call, result, st)
        type(run_context_t), intent(inout) :: ctx
        class(concept_t), pointer, intent(in) :: obj
        type(method_call_t), intent(in) :: call
        type(value_t), intent(out) :: result
        type(status_t), intent(out) :: st
        class(table_t), pointer :: t
        integer :: r
        if (.not. begin(ctx, obj, t, st)) return
        if (size(call%args) /= 1) then
            call set_error(st, STATUS_DECK_ERROR, 'a cell of a column is col[i]')
            return
        end if
        if (call%args(1)%kind /= VK_INT) then
            call set_error(st, STATUS_DECK_ERROR, 'a column is indexed by an integer, not ' // &
                kind_label(call%args(1)))
            return
        end if
        r = int(call%args(1)%i)
        if (r < 0) r = r + t%n_rows
        if (r < 0 .or. r >= t%n_rows) then
            call set_error(st, STATUS_DECK_ERROR, 'index ' // to_text(call%args(1)%i) // &
                ' out of range: the column has ' // to_text(int(t%n_rows, i4)) // ' cells')
            return
        end if
        result = cell_value(t, column_index(obj), r + 1)
    end subroutine column_item

    !> col.values(), col.not_none_values(): the cells as a list.
    subroutine column_values(ctx, obj, call, result, st)
        type(run_context_t), intent(inout) :: ctx
        class(concept_t), pointer, intent(in) :: obj
        type(method_call_t), intent(in) :: call
        type(value_t), intent(out) :: result
        type(status_t), intent(out) :: st
        class(table_t), pointer :: t
        type(value_t), allocatable :: cells(:)
        integer :: c, r
        if (.not. begin(ctx, obj, t, st)) return
        if (.not. takes_nothing(call, st)) return
        c = column_index(obj)
        if (call%name == 'values') then
            result = column_list_value(t, c)
            return
        end if
        allocate (cells(0))
        do r = 1, t%n_rows
            if (c == 0) exit
            if (t%columns(c)%present(r)) call append_value(cells, cell_value(t, c, r))
        end do
        result = sequence_value(VK_LIST, cells)
    end subroutine column_values

    !> The filters of table_py.Colonne: a Table of the rows whose cell passes.
    subroutine column_filter(ctx, obj, call, result, st)
        type(run_context_t), intent(inout) :: ctx
        class(concept_t), pointer, intent(in) :: obj
        type(method_call_t), intent(in) :: call
        type(value_t), intent(out) :: result
        type(status_t), intent(out) :: st
        class(table_t), pointer :: t
        type(value_t), allocatable :: given(:)
        logical, allocatable :: keep(:)
        real(dp) :: best
        integer :: c, r, k
        logical :: texts
        if (.not. begin(ctx, obj, t, st)) return
        c = column_index(obj)
        allocate (keep(t%n_rows), source=.false.)
        select case (call%name)
        case ('VIDE', 'NON_VIDE')
            if (.not. takes_nothing(call, st)) return
            do r = 1, t%n_rows
                keep(r) = .false.
                if (c > 0) keep(r) = t%columns(c)%present(r)
                if (call%name == 'VIDE') keep(r) = .not. keep(r)
            end do
        case ('MAXI', 'MINI', 'MAXI_ABS', 'MINI_ABS')
            if (.not. takes_nothing(call, st)) return
            if (c == 0) then
                call set_error(st, STATUS_DECK_ERROR, call%name // ' of a column the ' // &
                    'table has not')
                return
            end if
            if (t%columns(c)%kind == TABLE_TEXT) then
                call set_error(st, STATUS_DECK_ERROR, call%name // ' of a column of texts')
                return
            end if
            if (.not. any(t%columns(c)%present(1:t%n_rows))) then
                call set_error(st, STATUS_DECK_ERROR, call%name // ' of an empty column')
                return
            end if
            best = cell_real(t, c, findloc(t%columns(c)%present(1:t%n_rows), .true., dim=1))
            if (call%name(1:4) == 'MAXI' .or. call%name(1:4) == 'MINI') then
                do r = 1, t%n_rows
                    if (.not. t%columns(c)%present(r)) cycle
                    select case (call%name)
                    case ('MAXI')
                        best = max(best, cell_real(t, c, r))
                    case ('MINI')
                        best = min(best, cell_real(t, c, r))
                    case ('MAXI_ABS')
                        best = max(abs(best), abs(cell_real(t, c, r)))
                    case default
                        best = min(abs(best), abs(cell_real(t, c, r)))
                    end select
                end do
            end if
            do r = 1, t%n_rows
                if (.not. t%columns(c)%present(r)) cycle
                if (call%name == 'MAXI' .or. call%name == 'MINI') then
                    keep(r) = .not. (cell_real(t, c, r) < best .or. cell_real(t, c, r) > best)
                else
                    keep(r) = .not. (abs(cell_real(t, c, r)) < best .or. &
                                     abs(cell_real(t, c, r)) > best)
                end if
            end do
        case default
            if (size(call%args) /= 1) then
                call set_error(st, STATUS_DECK_ERROR, 'compare a column with one value or ' // &
                    'a list of values')
                return
            end if
            if (call%args(1)%kind == VK_TUPLE .or. call%args(1)%kind == VK_LIST) then
                allocate (given(nitems(call%args(1))))
                do k = 1, size(given)
                    given(k) = item(call%args(1), k)
                end do
            else
                allocate (given(1))
                given(1) = call%args(1)
            end if
            if (size(given) == 0) then
                call set_error(st, STATUS_DECK_ERROR, 'compare a column with at least one value')
                return
            end if
            texts = given(1)%kind == VK_STR
            do k = 1, size(given)
                if ((given(k)%kind == VK_STR) .neqv. texts .or. .not. (texts .or. &
                    given(k)%kind == VK_INT .or. given(k)%kind == VK_REAL .or. &
                    given(k)%kind == VK_BOOL .or. given(k)%kind == VK_NONE)) then
                    call set_error(st, STATUS_DECK_ERROR, 'compare a column with texts or ' // &
                        'with numbers, not ' // value_text(call%args(1)))
                    return
                end if
            end do
            do r = 1, t%n_rows
                keep(r) = passes(r)
                if (st%failed()) return
            end do
        end select
        call new_table(ctx, t, pack([(r, r=1, t%n_rows)], keep), result, st)
    contains
        !> Whether row r passes the comparison `call%name` with `given`.
        logical function passes(row) result(ok)
            integer, intent(in) :: row
            logical :: present, hit
            real(dp) :: x, bound
            integer :: j
            present = .false.
            if (c > 0) present = t%columns(c)%present(row)
            select case (call%name)
            case ('__eq__', '__ne__')
                hit = .false.
                do j = 1, size(given)
                    if (given(j)%kind == VK_NONE) then
                        hit = hit .or. .not. present
                    else if (.not. present) then
                        cycle
                    else if (texts) then
                        if (t%columns(c)%kind == TABLE_TEXT) hit = hit .or. &
                            trim(adjustl(t%columns(c)%texts(row)%s)) == trim(adjustl(given(j)%s))
                    else if (t%columns(c)%kind /= TABLE_TEXT) then
                        hit = hit .or. .not. (cell_real(t, c, row) < number(given(j)) .or. &
                                              cell_real(t, c, row) > number(given(j)))
                    end if
                end do
                ok = hit .neqv. (call%name == '__ne__')
            case default
                ok = .false.
                if (.not. present) return
                if (texts .or. t%columns(c)%kind == TABLE_TEXT) then
                    call set_error(st, STATUS_DECK_ERROR, 'a column of ' // &
                        trim(merge('texts  ', 'numbers', t%columns(c)%kind == TABLE_TEXT)) // &
                        ' compared by ' // call%name // ' with ' // value_text(call%args(1)))
                    return
                end if
                x = cell_real(t, c, row)
                bound = number(given(1))
                do j = 2, size(given)
                    if (call%name == '__lt__' .or. call%name == '__le__') then
                        bound = max(bound, number(given(j)))
                    else
                        bound = min(bound, number(given(j)))
                    end if
                end do
                select case (call%name)
                case ('__lt__')
                    ok = x < bound
                case ('__le__')
                    ok = x <= bound
                case ('__gt__')
                    ok = x > bound
                case default
                    ok = x >= bound
                end select
            end select
        end function passes
    end subroutine column_filter

    !> A number value as a real (booleans 0 / 1).
    pure real(dp) function number(v)
        type(value_t), intent(in) :: v
        if (v%kind == VK_REAL) then
            number = v%r
        else
            number = real(v%i, dp)
        end if
    end function number

    !> A numeric cell as a real.
    pure real(dp) function cell_real(t, c, r)
        class(table_t), intent(in) :: t
        integer, intent(in) :: c, r
        if (t%columns(c)%kind == TABLE_INT) then
            cell_real = real(t%columns(c)%ints(r), dp)
        else
            cell_real = t%columns(c)%reals(r)
        end if
    end function cell_real

end module table_methods
