!> Deck keywords shared by the commands that read tables: the table given at a keyword,
!> the FILTRE occurrences (NOM_PARA, CRIT_COMP, VALE / VALE_I / VALE_K, CRITERE,
!> PRECISION) read into table_filter_t and applied in order, each error located at the
!> occurrence's keyword; the TRI factor keyword.
module table_keywords
    use keyword_relocation, only: relocate_at => relocate_error
    use kinds, only: dp, i4, i8
    use strings, only: string_t, to_text, join_words
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use deck_concept, only: concept_t, concept_display_name
    use deck_value, only: value_t, VK_INT, VK_REAL, VK_STR, VK_BOOL, VK_TUPLE, VK_LIST, &
        unpack_value, value_list_t, kind_label
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use table_concept, only: table_t, table_find_column, TABLE_TEXT, table_cell_text, &
        table_cell_real, TABLE_INT
    use table_filter, only: table_filter_t, apply_table_filter, describe_filter, &
        FILTER_NO_VALUE, FILTER_INTS, FILTER_REALS, FILTER_TEXTS
    implicit none
    private

    !> Values of a column listed in an error message, at most.
    integer, parameter :: LISTED_VALUES = 12

    public :: table_of_keyword, read_filter, filter_rows_of_command, relocate_at, &
        column_values_text, read_mixed_values, filter_keyword, warn_at

contains

    !> The table given at `key` of `set`.
    !>  st : located at `key` when the concept is not a table
    subroutine table_of_keyword(set, key, t, st)
        class(keyword_set_t), intent(in) :: set
        character(len=*), intent(in) :: key
        type(table_t), pointer, intent(out) :: t
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: ptr
        t => null()
        call set%get_concept(key, ptr, st)
        if (st%failed()) return
        select type (ptr)
        type is (table_t)
            t => ptr
        class default
            call set%error_at(key, 'expected a table (table_sdaster), got ' // &
                              ptr%type_name(), st)
        end select
    end subroutine table_of_keyword

    !> One filter from an occurrence holding NOM_PARA, CRIT_COMP, VALE / VALE_I / VALE_K,
    !> CRITERE, PRECISION (FILTRE, or CALC_TABLE's ACTION with OPERATION='FILTRE').
    !>  cell_relative : TEST_TABLE's rules (table_filter)
    !>  st : located at the keyword at fault: a comparison without a value, a value with
    !>       VIDE/NON_VIDE/MAXI..., VALE of another type than reals (CALC_TABLE's VALE)
    subroutine read_filter(occ, cell_relative, f, st)
        type(keyword_set_t), intent(in) :: occ
        logical, intent(in) :: cell_relative
        type(table_filter_t), intent(out) :: f
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: criterion
        type(value_t), allocatable :: values(:)
        integer :: n_given, k
        f%cell_relative = cell_relative
        call occ%get_text('NOM_PARA', f%column, st)
        if (st%ok()) call occ%get_text('CRIT_COMP', f%operation, st)
        if (st%ok()) call occ%get_text('CRITERE', criterion, st)
        if (st%ok()) call occ%get_real('PRECISION', f%precision, st)
        if (st%failed()) return
        f%absolute = criterion == 'ABSOLU'
        n_given = count([occ%has('VALE'), occ%has('VALE_I'), occ%has('VALE_K')])
        select case (f%operation)
        case ('EQ', 'NE', 'LT', 'GT', 'LE', 'GE')
            if (n_given == 0) then
                call occ%error_at('CRIT_COMP', 'CRIT_COMP=''' // f%operation // &
                    ''' compares with a value: give VALE, VALE_I or VALE_K', st)
                return
            end if
        case ('REGEXP')
            if (.not. occ%has('VALE_K') .or. occ%has('VALE') .or. occ%has('VALE_I')) then
                call occ%error_at('CRIT_COMP', 'CRIT_COMP=''REGEXP'' takes the expression ' // &
                    'in VALE_K (and no VALE or VALE_I)', st)
                return
            end if
        case default
            if (n_given > 0) then
                call occ%error_at(first_value_keyword(occ), 'CRIT_COMP=''' // f%operation &
                    // ''' takes no value', st)
                return
            end if
        end select
        if (occ%has('VALE_I')) then
            f%value_kind = FILTER_INTS
            call read_ints(occ, 'VALE_I', f%ints, st)
        else if (occ%has('VALE_K')) then
            f%value_kind = FILTER_TEXTS
            call occ%get_texts('VALE_K', f%texts, st)
        else if (occ%has('VALE')) then
            f%value_kind = FILTER_REALS
            call read_mixed_values(occ, 'VALE', values)
            allocate (f%reals(size(values)))
            do k = 1, size(values)
                select case (values(k)%kind)
                case (VK_INT, VK_BOOL)
                    f%reals(k) = real(values(k)%i, dp)
                case (VK_REAL)
                    f%reals(k) = values(k)%r
                case default
                    call occ%error_at('VALE', 'a filter compares with numbers: VALE ' // &
                        'takes reals (VALE_K takes texts), got ' // kind_label(values(k)), st)
                    return
                end select
            end do
        end if
    end subroutine read_filter

    !> The integers given at `key`, as 64-bit integers.
    subroutine read_ints(occ, key, values, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        integer(i8), allocatable, intent(out) :: values(:)
        type(status_t), intent(inout) :: st
        integer(i4), allocatable :: small(:)
        call occ%get_ints(key, small, st)
        values = int(small, i8)
    end subroutine read_ints

    !> The values of `key` whatever their types (a single value gives a list of one).
    subroutine read_mixed_values(occ, key, values)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        type(value_t), allocatable, intent(out) :: values(:)
        type(value_t) :: v
        type(value_list_t) :: list
        v = occ%get_value(key)
        if (v%kind == VK_TUPLE .or. v%kind == VK_LIST) then
            list = unpack_value(v)
            values = list%items
        else
            allocate (values(1))
            values(1) = v
        end if
    end subroutine read_mixed_values

    !> The first of VALE, VALE_I, VALE_K the occurrence holds ('VALE' when none).
    function first_value_keyword(occ) result(key)
        type(keyword_set_t), intent(in) :: occ
        character(len=:), allocatable :: key
        key = 'VALE'
        if (occ%has('VALE_K')) key = 'VALE_K'
        if (occ%has('VALE_I')) key = 'VALE_I'
        if (occ%has('VALE')) key = 'VALE'
    end function first_value_keyword

    !> Applies the occurrences of factor keyword `factor` of `cmd` in order to the rows of
    !> `t`.
    !>  rows : out, the row indices that pass every filter
    !>  must_keep_one : when true, a filter that leaves no row is an error naming it, its
    !>                  occurrence, what the rows held before it
    !>  st : located at the occurrence's keyword at fault
    subroutine filter_rows_of_command(cmd, factor, t, cell_relative, must_keep_one, rows, st)
        type(command_t), intent(in) :: cmd
        character(len=*), intent(in) :: factor
        type(table_t), intent(in) :: t
        logical, intent(in) :: cell_relative, must_keep_one
        integer, allocatable, intent(out) :: rows(:)
        type(status_t), intent(out) :: st
        type(keyword_set_t) :: occ
        type(table_filter_t) :: f
        integer, allocatable :: before(:)
        integer :: k, r, column
        rows = [(r, r=1, t%n_rows)]
        do k = 1, cmd%count(factor)
            occ = cmd%occurrence(factor, k)
            call read_filter(occ, cell_relative, f, st)
            if (st%failed()) return
            before = rows
            call apply_table_filter(t, f, rows, st)
            if (st%failed()) then
                call relocate_at(occ, filter_keyword(occ, st%message), st)
                return
            end if
            if (must_keep_one .and. size(rows) == 0) then
                column = table_find_column(t, f%column)
                call occ%error_at('NOM_PARA', 'no row of table ' // &
                    concept_display_name(t) // ' passes this filter (' // describe_filter(f) &
                    // '); ' // trim(merge('before it    ', 'the table has', k > 1)) // ' ' // &
                    to_text(int(size(before), i4)) // ' rows, ' // f%column // ' = ' // &
                    column_values_text(t, column, before), st, STATUS_MODEL_ERROR)
                return
            end if
        end do
    end subroutine filter_rows_of_command

    !> The keyword of a filter occurrence an error from apply_table_filter belongs to: the
    !> values for a type mismatch, NOM_PARA otherwise.
    function filter_keyword(occ, message) result(key)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: message
        character(len=:), allocatable :: key
        key = 'NOM_PARA'
        if (index(message, 'filter it with') > 0 .or. index(message, 'REGEXP') > 0 .or. &
            index(message, 'regular expression') > 0) then
            key = first_value_keyword(occ)
        else if (index(message, 'CRIT_COMP') > 0) then
            key = 'CRIT_COMP'
        end if
    end function filter_keyword

    !> A located warning at `key` of `occ` (the .mess and stderr):
    !> `deck.comm:L:C: warning: COMMAND/FACTOR/KEY: message`.
    subroutine warn_at(ctx, occ, key, message)
        type(run_context_t), intent(inout) :: ctx
        class(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key, message
        character(len=:), allocatable :: file, path
        integer :: line, col
        call occ%location(key, file, line, col)
        path = occ%command
        if (allocated(occ%scope)) then
            if (len(occ%scope) > 0) path = path // '/' // occ%scope
        end if
        call ctx%write_warning(file // ':' // to_text(int(line, i4)) // ':' // &
            to_text(int(col, i4)) // ': warning: ' // path // '/' // key // ': ' // message)
    end subroutine warn_at

    !> The values of column `column` in rows `rows` (at most LISTED_VALUES, then '...'),
    !> absent cells as '-', for messages.
    function column_values_text(t, column, rows) result(text)
        type(table_t), intent(in) :: t
        integer, intent(in) :: column
        integer, intent(in) :: rows(:)
        character(len=:), allocatable :: text
        type(string_t), allocatable :: words(:)
        integer :: k, n
        if (column == 0) then
            text = '(no such column)'
            return
        end if
        n = min(size(rows), LISTED_VALUES)
        allocate (words(n))
        do k = 1, n
            if (.not. t%columns(column)%present(rows(k))) then
                words(k)%s = '-'
            else if (t%columns(column)%kind == TABLE_TEXT) then
                words(k)%s = '''' // table_cell_text(t, column, rows(k)) // ''''
            else if (t%columns(column)%kind == TABLE_INT) then
                words(k)%s = to_text(t%columns(column)%ints(rows(k)))
            else
                words(k)%s = to_text(table_cell_real(t, column, rows(k)))
            end if
        end do
        text = join_words(words, ', ')
        if (size(rows) > n) text = text // ', ...'
        if (size(rows) == 0) text = '(no row)'
    end function column_values_text

end module table_keywords
