!> TEST_TABLE (U4.92.03): checks one cell of a table, or a column reduced by TYPE_TEST, against
!> the deck's VALE_CALC (and VALE_REFE with REFERENCE), as Code_Aster's op0177 does:
!>  - FILTRE occurrences select rows in turn (TEST_TABLE's own rules: table_filter); a
!>    filter that leaves no row is an error naming it and what the column held before it;
!>  - without TYPE_TEST the filters must leave exactly one row, whose cell of NOM_PARA is
!>    tested; with TYPE_TEST (SOMM_ABS, SOMM, MAX, MIN) the present cells of NOM_PARA in the
!>    rows left are reduced to one value;
!>  - the value's type must be the column's: VALE_CALC for R, VALE_CALC_I for I,
!>    VALE_CALC_K for K columns;
!>  - the checks and their lines: test_value_check (listings.md's TEST_RESU layout).
module test_table_command
    use kinds, only: dp, i4, i8
    use strings, only: string_t, to_text
    use status, only: status_t, STATUS_MODEL_ERROR
    use deck_concept, only: concept_t, concept_display_name
    use deck_command, only: command_t
    use run_context, only: run_context_t
    use table_concept, only: table_t, table_require_column, table_kind_label, TABLE_INT, &
        TABLE_REAL, TABLE_TEXT
    use table_keywords, only: table_of_keyword, filter_rows_of_command, relocate_at, &
        column_values_text
    use table_reduce, only: reduce_reals, reduce_ints
    use test_value_check, only: test_request_t, tested_value_t, read_test_request, &
        test_check_lines, id_line_pair, write_test_block, TESTED_REAL, TESTED_INT, &
        TESTED_TEXT, tested_kind_name
    implicit none
    private

    public :: run_test_table

contains

    !> Handler of TEST_TABLE (doc/architecture.md "Writing a command handler").
    !>  st : located errors: not a table, a column that does not exist (naming those that
    !>       do), a filter that leaves no row, several rows without TYPE_TEST, an empty
    !>       cell, a value type that is not the column's
    subroutine run_test_table(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(table_t), pointer :: t
        type(test_request_t) :: req
        type(tested_value_t) :: value
        character(len=:), allocatable :: para, type_test
        integer, allocatable :: rows(:)
        integer :: column, n_ok, n_nook
        type(string_t) :: titles(3), values(3), id_lines(2)
        type(string_t), allocatable :: lines(:)
        if (allocated(result)) deallocate (result)
        call table_of_keyword(cmd, 'TABLE', t, st)
        if (st%ok()) call read_test_request(cmd, req, st)
        if (st%ok()) call cmd%get_text('NOM_PARA', para, st)
        if (st%failed()) return
        type_test = ''
        if (cmd%has('TYPE_TEST')) call cmd%get_text('TYPE_TEST', type_test, st)
        if (st%failed()) return
        call filter_rows_of_command(cmd, 'FILTRE', t, .true., .true., rows, st)
        if (st%failed()) return
        call table_require_column(t, para, column, st)
        if (st%failed()) then
            call relocate_at(cmd, 'NOM_PARA', st)
            return
        end if
        call check_value_type(cmd, t, column, req%kind, st)
        if (st%failed()) return
        if (len(type_test) > 0) then
            call reduce_column(cmd, t, column, rows, type_test, value, st)
        else
            call single_cell(cmd, t, column, rows, value, st)
        end if
        if (st%failed()) return
        titles(1)%s = 'TABLE'
        titles(2)%s = 'NOM_PARA'
        titles(3)%s = 'TYPE_TEST'
        values(1)%s = concept_display_name(t)
        values(2)%s = para
        values(3)%s = type_test
        if (len(type_test) > 0) then
            call id_line_pair(titles, values, id_lines)
        else
            call id_line_pair(titles(1:2), values(1:2), id_lines)
        end if
        n_ok = 0
        n_nook = 0
        call test_check_lines(req, value, lines, n_ok, n_nook)
        call write_test_block(ctx, 'TEST_TABLE', id_lines, lines)
    end subroutine run_test_table

    !> VALE_CALC goes with R columns, VALE_CALC_I with I, VALE_CALC_K with K.
    subroutine check_value_type(cmd, t, column, kind, st)
        type(command_t), intent(in) :: cmd
        type(table_t), intent(in) :: t
        integer, intent(in) :: column, kind
        type(status_t), intent(inout) :: st
        integer :: wanted
        character(len=:), allocatable :: key
        select case (t%columns(column)%kind)
        case (TABLE_INT)
            wanted = TESTED_INT
        case (TABLE_REAL)
            wanted = TESTED_REAL
        case default
            wanted = TESTED_TEXT
        end select
        if (wanted == kind) return
        key = 'VALE_CALC'
        if (kind == TESTED_INT) key = 'VALE_CALC_I'
        if (kind == TESTED_TEXT) key = 'VALE_CALC_K'
        call cmd%error_at(key, 'column ' // t%columns(column)%name // ' of table ' // &
            concept_display_name(t) // ' holds ' // table_kind_label(t%columns(column)) // &
            ' values: test it with ' // tested_kind_name(wanted), st)
    end subroutine check_value_type

    !> The one cell the filters leave.
    subroutine single_cell(cmd, t, column, rows, value, st)
        type(command_t), intent(in) :: cmd
        type(table_t), intent(in) :: t
        integer, intent(in) :: column
        integer, intent(in) :: rows(:)
        type(tested_value_t), intent(out) :: value
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: where
        where = 'TABLE'
        if (cmd%count('FILTRE') > 0) where = 'FILTRE'
        if (size(rows) /= 1) then
            call cmd%error_at(where, to_text(int(size(rows), i4)) // ' rows of table ' // &
                concept_display_name(t) // ' pass the filters: TEST_TABLE tests one cell ' // &
                '(add a FILTRE, or give TYPE_TEST); ' // t%columns(column)%name // &
                ' in those rows: ' // column_values_text(t, column, rows), st, &
                STATUS_MODEL_ERROR)
            return
        end if
        if (.not. t%columns(column)%present(rows(1))) then
            call cmd%error_at('NOM_PARA', 'the cell of column ' // t%columns(column)%name // &
                ' in the row the filters select is empty', st, STATUS_MODEL_ERROR)
            return
        end if
        call cell_value(t, column, rows(1), value)
    end subroutine single_cell

    subroutine cell_value(t, column, row, value)
        type(table_t), intent(in) :: t
        integer, intent(in) :: column, row
        type(tested_value_t), intent(out) :: value
        select case (t%columns(column)%kind)
        case (TABLE_INT)
            value%kind = TESTED_INT
            value%i = t%columns(column)%ints(row)
        case (TABLE_REAL)
            value%kind = TESTED_REAL
            value%r = t%columns(column)%reals(row)
        case default
            value%kind = TESTED_TEXT
            value%k = t%columns(column)%texts(row)%s
        end select
    end subroutine cell_value

    !> TYPE_TEST: SOMM_ABS, SOMM, MAX or MIN of the present cells of the rows.
    subroutine reduce_column(cmd, t, column, rows, type_test, value, st)
        type(command_t), intent(in) :: cmd
        type(table_t), intent(in) :: t
        integer, intent(in) :: column
        integer, intent(in) :: rows(:)
        character(len=*), intent(in) :: type_test
        type(tested_value_t), intent(out) :: value
        type(status_t), intent(inout) :: st
        integer, allocatable :: present_rows(:)
        real(dp), allocatable :: x(:)
        integer(i8), allocatable :: n(:)
        associate (col => t%columns(column))
            if (col%kind == TABLE_TEXT) then
                call cmd%error_at('TYPE_TEST', 'TYPE_TEST=''' // type_test // ''' reduces ' // &
                    'numbers: column ' // col%name // ' holds texts (' // &
                    table_kind_label(col) // ')', st)
                return
            end if
            present_rows = pack(rows, col%present(rows))
            if (size(present_rows) == 0) then
                call cmd%error_at('TYPE_TEST', 'no row left by the filters has a value in ' // &
                    'column ' // col%name // ': there is nothing to reduce', st, &
                    STATUS_MODEL_ERROR)
                return
            end if
            if (col%kind == TABLE_INT) then
                value%kind = TESTED_INT
                n = col%ints(present_rows)
                call reduce_ints(n, type_test, value%i, st)
            else
                value%kind = TESTED_REAL
                x = col%reals(present_rows)
                call reduce_reals(x, type_test, value%r, st)
            end if
            if (st%failed()) call relocate_at(cmd, 'TYPE_TEST', st)
        end associate
    end subroutine reduce_column

end module test_table_command
