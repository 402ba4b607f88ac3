!> Operations on whole tables (CALC_TABLE's actions), as Code_Aster's Python Table does
!> them (code_aster/Objects/table_py.py), each in O(n log n) at most:
!>  - combine (COMB, `merge`): the columns of the second table added to the first; with
!>    key columns, a row of the second whose key appears exactly once in each table
!>    overwrites the matching row's cells, any other row is appended (RESTREINT='OUI':
!>    dropped); without keys every row is appended; FORMAT_R compares reals as printed;
!>  - unique rows (UNIQUE, `remove_twins`): the first row of each key kept;
!>  - rows and columns from deck values (AJOUT_LIGNE, AJOUT_COLONNE), a column from a
!>    formula of other columns (OPER, `fromfunction`: a row missing a parameter gets no
!>    value), statistics (STATISTIQUES), reductions (CALCUL);
!>  - the final clean-up Code_Aster's CALC_TABLE does when it stores its table (CREA_TABLE
!>    from `dict_CREA_TABLE`): columns without any value and rows without any value go.
!> Keys compare values exactly (an integer equals the same real; 0 equals -0), through a
!> text key per row sorted once.
module table_operations
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use kinds, only: dp, i4, i8
    use strings, only: string_t, to_text, join_words
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use python_format, only: real_format_t, format_real
    use deck_concept, only: concept_display_name
    use deck_value, only: value_t, VK_INT, VK_REAL, VK_STR, VK_BOOL, kind_label, append_string
    use function_concept, only: function_concept_t, param_binding_t
    use table_concept, only: table_label, table_t, table_column_t, table_find_column, &
        table_require_column, table_add_column, table_add_rows, table_set_int, &
        table_set_real, table_set_text, table_copy_cell, table_select_rows, &
        table_select_columns, table_replace_rows, table_text_width_for, TABLE_INT, &
        TABLE_REAL, TABLE_TEXT, TABLE_DEFAULT_TEXT_WIDTH, table_kind_label, &
        table_is_number, MAX_TABLE_ROWS
    use table_sort, only: compare_texts, text_order
    use table_reduce, only: reduce_reals, reduce_ints
    implicit none
    private

    public :: table_combine, table_unique_rows, table_drop_empty_columns, &
        table_append_row, table_add_value_column, table_add_formula_column, &
        table_add_statistics, table_calculation, row_keys

contains

    ! ---- keys ---------------------------------------------------------------------------

    !> A text key per row of `t` over columns `columns`: equal keys for equal values.
    !>  format_r : when allocated, reals compare as this format prints them
    subroutine row_keys(t, columns, keys, format_r)
        type(table_t), intent(in) :: t
        integer, intent(in) :: columns(:)
        type(string_t), allocatable, intent(out) :: keys(:)
        type(real_format_t), intent(in), optional :: format_r
        integer :: r, k
        allocate (keys(t%n_rows))
        do r = 1, t%n_rows
            keys(r)%s = ''
            do k = 1, size(columns)
                keys(r)%s = keys(r)%s // cell_key(t%columns(columns(k)), r, format_r) // '|'
            end do
        end do
    end subroutine row_keys

    !> The key of one cell: '-' absent; numbers by their binary value (integers below
    !> 2**53 as the equal real); texts with their length.
    function cell_key(col, row, format_r) result(key)
        type(table_column_t), intent(in) :: col
        integer, intent(in) :: row
        type(real_format_t), intent(in), optional :: format_r
        character(len=:), allocatable :: key
        if (.not. col%present(row)) then
            key = '-'
            return
        end if
        select case (col%kind)
        case (TABLE_INT)
            if (abs(col%ints(row)) < 2_i8**53) then
                key = real_key(real(col%ints(row), dp), format_r)
            else
                key = 'I' // to_text(col%ints(row))
            end if
        case (TABLE_REAL)
            key = real_key(col%reals(row), format_r)
        case default
            key = 'K' // to_text(int(len(col%texts(row)%s), i4)) // ':' // col%texts(row)%s
        end select
    end function cell_key

    function real_key(x, format_r) result(key)
        real(dp), intent(in) :: x
        type(real_format_t), intent(in), optional :: format_r
        character(len=:), allocatable :: key
        character(len=16) :: buf
        if (present(format_r)) then
            key = 'F' // trim(adjustl(format_real(format_r, x)))
            return
        end if
        if (.not. abs(x) > 0.0_dp) then
            key = 'R0'                                 ! 0 and -0 are one value
            return
        end if
        write (buf, '(z16.16)') transfer(x, 0_i8)
        key = 'R' // buf
    end function real_key

    !> Whether each row's key is held by that row only; a row with an absent key cell
    !> (`complete` false) is never unique.
    subroutine unique_key_rows(keys, order, complete, unique)
        type(string_t), intent(in) :: keys(:)
        integer, intent(in) :: order(:)
        logical, intent(in) :: complete(:)
        logical, allocatable, intent(out) :: unique(:)
        integer :: i, j
        allocate (unique(size(keys)), source=.false.)
        i = 1
        do while (i <= size(order))
            j = i
            do while (j < size(order))
                if (keys(order(j + 1))%s /= keys(order(i))%s) exit
                j = j + 1
            end do
            if (j == i .and. complete(order(i))) unique(order(i)) = .true.
            i = j + 1
        end do
    end subroutine unique_key_rows

    !> Whether each row has a value in every key column.
    function keys_complete(t, columns) result(complete)
        type(table_t), intent(in) :: t
        integer, intent(in) :: columns(:)
        logical, allocatable :: complete(:)
        integer :: k
        allocate (complete(t%n_rows), source=.true.)
        do k = 1, size(columns)
            complete = complete .and. t%columns(columns(k))%present(1:t%n_rows)
        end do
    end function keys_complete

    ! ---- COMB ---------------------------------------------------------------------------

    !> COMB: `t` receives the columns and rows of `other` (see the module's header).
    !>  labels : key columns (in both tables)
    !>  st : a key column missing in a table (naming its columns), types that do not mix
    subroutine table_combine(t, other, labels, restrict, t_out, st, format_r)
        type(table_t), intent(in) :: t, other
        type(string_t), intent(in) :: labels(:)
        logical, intent(in) :: restrict
        type(table_t), intent(out) :: t_out
        type(status_t), intent(inout) :: st
        type(real_format_t), intent(in), optional :: format_r
        integer, allocatable :: keys1(:), keys2(:), target_row(:), map2(:), order1(:), &
            order2(:)
        type(string_t), allocatable :: k1(:), k2(:)
        logical, allocatable :: unique1(:), unique2(:)
        integer :: k, c, i, j, r2, n_new, row
        allocate (keys1(size(labels)), keys2(size(labels)))
        do k = 1, size(labels)
            call table_require_column(t, labels(k)%s, keys1(k), st)
            if (st%ok()) call table_require_column(other, labels(k)%s, keys2(k), st)
            if (st%failed()) return
        end do
        t_out = table_select_rows(t, [(i, i=1, t%n_rows)])
        ! the columns of `other` that `t` lacks, with their types
        allocate (map2(other%n_columns))
        do c = 1, other%n_columns
            map2(c) = table_find_column(t_out, other%columns(c)%name)
            if (map2(c) > 0) cycle
            call table_add_column(t_out, other%columns(c)%name, other%columns(c)%kind, &
                                  map2(c), st, other%columns(c)%width)
            if (st%failed()) return
        end do
        ! the row of t each row of `other` goes to (0: appended)
        allocate (target_row(other%n_rows), source=0)
        if (size(labels) > 0) then
            call row_keys(t, keys1, k1, format_r)
            call row_keys(other, keys2, k2, format_r)
            order1 = text_order(k1)
            order2 = text_order(k2)
            call unique_key_rows(k1, order1, keys_complete(t, keys1), unique1)
            call unique_key_rows(k2, order2, keys_complete(other, keys2), unique2)
            i = 1; j = 1
            do while (i <= size(order1) .and. j <= size(order2))
                select case (compare_texts(k1(order1(i))%s, k2(order2(j))%s))
                case (-1)
                    i = i + 1
                case (1)
                    j = j + 1
                case default
                    if (unique1(order1(i)) .and. unique2(order2(j))) &
                        target_row(order2(j)) = order1(i)
                    i = i + 1; j = j + 1
                end select
            end do
        end if
        n_new = 0
        if (.not. restrict) n_new = count(target_row == 0)
        if (t_out%n_rows + n_new > MAX_TABLE_ROWS) then
            call set_error(st, STATUS_MODEL_ERROR, 'the combined table would have more ' // &
                'than ' // to_text(int(MAX_TABLE_ROWS, i4)) // ' rows')
            return
        end if
        row = t_out%n_rows
        call table_add_rows(t_out, n_new)
        do r2 = 1, other%n_rows
            if (target_row(r2) == 0) then
                if (restrict) cycle
                row = row + 1
                i = row
            else
                i = target_row(r2)
            end if
            do c = 1, other%n_columns
                if (.not. other%columns(c)%present(r2)) cycle   ! a dict update: present cells
                call table_copy_cell(other, c, r2, t_out, map2(c), i, st)
                if (st%failed()) return
            end do
        end do
    end subroutine table_combine

    ! ---- UNIQUE -------------------------------------------------------------------------

    !> Keeps the first row of each key (absent cells are a value of their own).
    subroutine table_unique_rows(t, labels, st, format_r)
        type(table_t), intent(inout) :: t
        type(string_t), intent(in) :: labels(:)
        type(status_t), intent(inout) :: st
        type(real_format_t), intent(in), optional :: format_r
        integer, allocatable :: columns(:), order(:)
        type(string_t), allocatable :: keys(:)
        logical, allocatable :: keep(:)
        integer :: k, r
        allocate (columns(size(labels)))
        do k = 1, size(labels)
            call table_require_column(t, labels(k)%s, columns(k), st)
            if (st%failed()) return
        end do
        call row_keys(t, columns, keys, format_r)
        order = text_order(keys)       ! stable: the first row of a key comes first
        allocate (keep(t%n_rows), source=.false.)
        do k = 1, size(order)
            if (k > 1) then
                if (keys(order(k))%s == keys(order(k - 1))%s) cycle
            end if
            keep(order(k)) = .true.
        end do
        call table_replace_rows(t, pack([(r, r=1, t%n_rows)], keep))
    end subroutine table_unique_rows

    ! ---- clean-up -----------------------------------------------------------------------

    !> Removes the columns without any value (their names in `dropped`) and the rows
    !> without any value.
    subroutine table_drop_empty_columns(t, dropped)
        type(table_t), intent(inout) :: t
        type(string_t), allocatable, intent(out) :: dropped(:)
        type(table_t) :: kept
        character(len=:), allocatable :: name
        logical, allocatable :: used(:), row_used(:)
        integer :: c, r
        allocate (used(t%n_columns), row_used(t%n_rows))
        do c = 1, t%n_columns
            used(c) = any(t%columns(c)%present(1:t%n_rows))
        end do
        allocate (dropped(0))
        do c = 1, t%n_columns
            if (.not. used(c)) call append_string(dropped, t%columns(c)%name)
        end do
        if (size(dropped) > 0) then
            if (allocated(t%name)) name = t%name
            kept = table_select_columns(t, pack([(c, c=1, t%n_columns)], used))
            t = kept
            if (allocated(name)) t%name = name
        end if
        row_used = .false.
        do c = 1, t%n_columns
            row_used = row_used .or. t%columns(c)%present(1:t%n_rows)
        end do
        if (.not. all(row_used)) call table_replace_rows(t, pack([(r, r=1, t%n_rows)], row_used))
    end subroutine table_drop_empty_columns

    ! ---- deck values --------------------------------------------------------------------

    !> The column type of a deck value: I, R or a text (K24 or the width the text needs).
    subroutine value_type(v, kind, width, st)
        type(value_t), intent(in) :: v
        integer, intent(out) :: kind, width
        type(status_t), intent(inout) :: st
        width = 0
        select case (v%kind)
        case (VK_INT, VK_BOOL)
            kind = TABLE_INT
        case (VK_REAL)
            kind = TABLE_REAL
        case (VK_STR)
            kind = TABLE_TEXT
            width = max(TABLE_DEFAULT_TEXT_WIDTH, table_text_width_for(len(v%s)))
            if (table_text_width_for(len(v%s)) == 0) call set_error(st, STATUS_MODEL_ERROR, &
                'a table text has at most 80 characters; ''' // v%s // ''' has ' // &
                to_text(int(len(v%s), i4)))
        case default
            kind = 0
            call set_error(st, STATUS_MODEL_ERROR, 'a table holds integers, reals and ' // &
                'texts, not ' // kind_label(v))
        end select
    end subroutine value_type

    !> Sets cell (row, column) from a deck value.
    subroutine set_from_value(t, column, row, v, st)
        type(table_t), intent(inout) :: t
        integer, intent(in) :: column, row
        type(value_t), intent(in) :: v
        type(status_t), intent(inout) :: st
        select case (v%kind)
        case (VK_INT, VK_BOOL)
            call table_set_int(t, column, row, v%i, st)
        case (VK_REAL)
            call table_set_real(t, column, row, v%r, st)
        case (VK_STR)
            call table_set_text(t, column, row, v%s, st)
        case default
            call set_error(st, STATUS_MODEL_ERROR, 'a table holds integers, reals and ' // &
                'texts, not ' // kind_label(v))
        end select
    end subroutine set_from_value

    !> AJOUT_LIGNE: a row with values(k) in column names(k) (new columns are created).
    subroutine table_append_row(t, names, values, st)
        type(table_t), intent(inout) :: t
        type(string_t), intent(in) :: names(:)
        type(value_t), intent(in) :: values(:)
        type(status_t), intent(inout) :: st
        integer :: k, c, kind, width
        if (t%n_rows + 1 > MAX_TABLE_ROWS) then
            call set_error(st, STATUS_MODEL_ERROR, 'a table has at most ' // &
                to_text(int(MAX_TABLE_ROWS, i4)) // ' rows')
            return
        end if
        call table_add_rows(t, 1)
        do k = 1, size(names)
            c = table_find_column(t, names(k)%s)
            if (c == 0) then
                call value_type(values(k), kind, width, st)
                if (st%failed()) return
                call table_add_column(t, names(k)%s, kind, c, st, width)
                if (st%failed()) return
            end if
            call set_from_value(t, c, t%n_rows, values(k), st)
            if (st%failed()) then
                st%message = names(k)%s // ': ' // st%message
                return
            end if
        end do
    end subroutine table_append_row

    !> AJOUT_COLONNE: a new column `name` holding values(k) in row k (values beyond the
    !> rows are not used, rows beyond the values get none), or the one value in every row
    !> (`constant`). Nothing is added to a table without rows (as Code_Aster).
    !>  st : a column of that name exists, values of types that do not mix
    subroutine table_add_value_column(t, name, values, constant, st)
        type(table_t), intent(inout) :: t
        character(len=*), intent(in) :: name
        type(value_t), intent(in) :: values(:)
        logical, intent(in) :: constant
        type(status_t), intent(inout) :: st
        integer :: c, r, kind, width, n, k
        if (t%n_rows == 0 .or. size(values) == 0) return
        if (table_find_column(t, name) > 0) then
            call set_error(st, STATUS_MODEL_ERROR, table_label(t) // &
                ' already has a column ' // name)
            return
        end if
        call value_type(values(1), kind, width, st)
        if (st%failed()) return
        if (kind == TABLE_TEXT) then
            do k = 1, size(values)
                if (values(k)%kind == VK_STR) width = max(width, &
                    table_text_width_for(len(values(k)%s)))
            end do
        end if
        call table_add_column(t, name, kind, c, st, width)
        if (st%failed()) return
        n = t%n_rows
        if (.not. constant) n = min(t%n_rows, size(values))
        do r = 1, n
            if (constant) then
                call set_from_value(t, c, r, values(1), st)
            else
                call set_from_value(t, c, r, values(r), st)
            end if
            if (st%failed()) return
        end do
    end subroutine table_add_value_column

    !> OPER: a new column `name` = f(columns), row by row (no value where a parameter
    !> has none).
    !>  st : a parameter column missing (naming the table's columns), the column exists, a
    !>       text parameter, an evaluation failing (naming the row)
    subroutine table_add_formula_column(t, name, f, parameters, st)
        type(table_t), intent(inout) :: t
        character(len=*), intent(in) :: name
        class(function_concept_t), intent(in) :: f
        type(string_t), intent(in) :: parameters(:)
        type(status_t), intent(inout) :: st
        integer, allocatable :: columns(:)
        type(param_binding_t) :: binding
        character(len=64), allocatable :: given(:)
        type(string_t), allocatable :: formal(:)
        real(dp), allocatable :: args(:)
        real(dp) :: y
        integer :: k, r, c
        if (table_find_column(t, name) > 0) then
            call set_error(st, STATUS_MODEL_ERROR, table_label(t) // &
                ' already has a column ' // name // ' (OPER makes a new column)')
            return
        end if
        allocate (columns(size(parameters)))
        do k = 1, size(parameters)
            call table_require_column(t, parameters(k)%s, columns(k), st)
            if (st%failed()) return
            if (.not. table_is_number(t%columns(columns(k)))) then
                call set_error(st, STATUS_MODEL_ERROR, 'column ' // parameters(k)%s // &
                    ' holds texts (' // table_kind_label(t%columns(columns(k))) // &
                    '): a formula takes numbers')
                return
            end if
        end do
        ! the formula's own parameter names, bound in order to the columns
        formal = f%parameters()
        allocate (given(size(formal)))
        do k = 1, size(formal)
            given(k) = formal(k)%s
        end do
        call f%bind(given, binding)
        allocate (args(size(columns)))
        call table_add_column(t, name, TABLE_REAL, c, st)
        if (st%failed()) return
        do r = 1, t%n_rows
            if (.not. all([(t%columns(columns(k))%present(r), k=1, size(columns))])) cycle
            do k = 1, size(columns)
                if (t%columns(columns(k))%kind == TABLE_INT) then
                    args(k) = real(t%columns(columns(k))%ints(r), dp)
                else
                    args(k) = t%columns(columns(k))%reals(r)
                end if
            end do
            call f%evaluate(binding, args, y, st)
            if (st%ok() .and. .not. ieee_is_finite(y)) call set_error(st, STATUS_MODEL_ERROR, &
                'the formula''s value is not a finite number')
            if (st%failed()) then
                st%message = 'row ' // to_text(int(r, i4)) // ' (' // &
                    join_words(parameters, ', ') // ' = ' // numbers_text(args) // '): ' // &
                    st%message
                return
            end if
            call table_set_real(t, c, r, y, st)
        end do
    end subroutine table_add_formula_column

    function numbers_text(x) result(text)
        real(dp), intent(in) :: x(:)
        character(len=:), allocatable :: text
        integer :: k
        text = ''
        do k = 1, size(x)
            if (k > 1) text = text // ', '
            text = text // to_text(x(k))
        end do
    end function numbers_text

    !> STATISTIQUES: columns STAT_VALE (I) and STAT_NOM (K8) holding the number of rows,
    !> of columns and of absent cells in their first three rows (rows are added when the
    !> table has fewer).
    subroutine table_add_statistics(t, st)
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        integer(i8) :: values(3)
        character(len=11), parameter :: NAMES(3) = ['NB_LIGNES  ', 'NB_COLONNES', &
                                                    'NB_VIDE    ']
        integer :: c, cv, cn, k
        if (table_find_column(t, 'STAT_NOM') > 0 .or. table_find_column(t, 'STAT_VALE') > 0) then
            call set_error(st, STATUS_MODEL_ERROR, table_label(t) // &
                ' already has a column STAT_NOM or STAT_VALE')
            return
        end if
        values(1) = t%n_rows
        values(2) = t%n_columns
        values(3) = 0
        do c = 1, t%n_columns
            values(3) = values(3) + count(.not. t%columns(c)%present(1:t%n_rows))
        end do
        call table_add_column(t, 'STAT_VALE', TABLE_INT, cv, st)
        if (st%ok()) call table_add_column(t, 'STAT_NOM', TABLE_TEXT, cn, st, 16)
        if (st%failed()) return
        if (t%n_rows < 3) call table_add_rows(t, 3 - t%n_rows)
        do k = 1, 3
            call table_set_int(t, cv, k, values(k), st)
            call table_set_text(t, cn, k, trim(NAMES(k)), st)
        end do
    end subroutine table_add_statistics

    !> CALCUL: a new table of the numeric columns `names` and TYPE_CALCUL (K8), a row per
    !> reduction (MAXI, MINI, SOMM, MOY, MAXI_ABS, MINI_ABS, SOMM_ABS) over the values
    !> present.
    subroutine table_calculation(t, names, operations, t_out, st)
        type(table_t), intent(in) :: t
        type(string_t), intent(in) :: names(:), operations(:)
        type(table_t), intent(out) :: t_out
        type(status_t), intent(inout) :: st
        integer, allocatable :: columns(:), kept(:)
        integer :: k, j, c, ct
        real(dp) :: x
        integer(i8) :: n
        allocate (columns(size(names)))
        do k = 1, size(names)
            call table_require_column(t, names(k)%s, columns(k), st)
            if (st%failed()) return
            if (.not. table_is_number(t%columns(columns(k)))) then
                call set_error(st, STATUS_MODEL_ERROR, 'column ' // names(k)%s // &
                    ' holds texts (' // table_kind_label(t%columns(columns(k))) // &
                    '): CALCUL reduces numbers')
                return
            end if
        end do
        ! the columns in the table's order (Code_Aster keeps them so)
        kept = pack([(c, c=1, t%n_columns)], [(any(columns == c), c=1, t%n_columns)])
        t_out = table_select_columns(t, kept)
        call table_replace_rows(t_out, [integer ::])
        call table_add_column(t_out, 'TYPE_CALCUL', TABLE_TEXT, ct, st, 8)
        if (st%failed()) return
        call table_add_rows(t_out, size(operations))
        do j = 1, size(operations)
            call table_set_text(t_out, ct, j, operations(j)%s, st)
            do k = 1, size(kept)
                associate (col => t%columns(kept(k)))
                    if (.not. any(col%present(1:t%n_rows))) cycle
                    if (col%kind == TABLE_INT .and. operations(j)%s /= 'MOY') then
                        call reduce_ints(pack(col%ints(1:t%n_rows), col%present(1:t%n_rows)), &
                                         operations(j)%s, n, st)
                        if (st%ok()) call table_set_int(t_out, k, j, n, st)
                    else if (col%kind == TABLE_INT) then
                        call reduce_reals(real(pack(col%ints(1:t%n_rows), &
                            col%present(1:t%n_rows)), dp), operations(j)%s, x, st)
                        if (st%ok()) call table_set_real(t_out, k, j, x, st)
                    else
                        call reduce_reals(pack(col%reals(1:t%n_rows), &
                            col%present(1:t%n_rows)), operations(j)%s, x, st)
                        if (st%ok()) call table_set_real(t_out, k, j, x, st)
                    end if
                    if (st%failed()) then
                        st%message = col%name // ', ' // operations(j)%s // ': ' // st%message
                        return
                    end if
                end associate
            end do
        end do
    end subroutine table_calculation

end module table_operations
