!> TEST_TABLE (U4.92.03): checks one cell of a table, or a column reduced by TYPE_TEST, against
!> the deck's VALE_CALC (and VALE_REFE with REFERENCE), as Code_Aster's op0177 does:
!>  - FILTRE occurrences select rows in turn (TEST_TABLE's own rules: table_filter); a
!>    filter that leaves no row is an error naming it and what the column held before it;
!>  - without TYPE_TEST the filters must leave exactly one row, whose cell of NOM_PARA is
!>    tested; with TYPE_TEST (SOMM_ABS, SOMM, MAX, MIN) the present cells of NOM_PARA in the
!>    rows left are reduced to one value;
!>  - the value's type must be the column's: VALE_CALC for R, VALE_CALC_I for I,
!>    VALE_CALC_K for K columns;
!>  - the checks and their lines are TEST_RESU's (test_resu_checks, listings.md): closest
!>    VALE_CALC, VALE_ABS, ORDRE_GRANDEUR, the skip of a zero VALE_CALC; texts
!>    (VALE_CALC_K) are equal or not.
module test_table_command
    use kinds, only: dp, i4, i8
    use strings, only: string_t, to_text
    use status, only: status_t, STATUS_MODEL_ERROR
    use deck_concept, only: concept_t, concept_display_name
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use table_concept, only: table_t, table_require_column, table_kind_label, TABLE_INT, &
        TABLE_REAL, TABLE_TEXT
    use table_keywords, only: table_of_keyword, filter_rows_of_command, relocate_at, &
        column_values_text
    use table_reduce, only: reduce_reals, reduce_ints
    use test_resu_format, only: test_check_t, test_resu_header_line, TEST_RESU_NO_LEGEND
    use test_resu_checks, only: read_checks, write_test_block, test_columns_t, add_column, &
        listing_safe_text, compact_text
    implicit none
    private

    !> Kinds of tested values.
    integer, parameter :: TESTED_REAL = 1, TESTED_INT = 2, TESTED_TEXT = 3

    !> The tested value.
    type :: tested_value_t
        integer :: kind = TESTED_REAL
        real(dp) :: r = 0.0_dp
        integer(i8) :: i = 0
        character(len=:), allocatable :: k
    end type tested_value_t

    public :: run_test_table, text_check_line

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
        type(tested_value_t) :: value
        type(test_check_t), allocatable :: checks(:)
        type(test_columns_t) :: cols
        character(len=:), allocatable :: para, type_test
        integer, allocatable :: rows(:)
        integer :: column, kind
        logical :: integers
        if (allocated(result)) deallocate (result)
        call table_of_keyword(cmd, 'TABLE', t, st)
        if (st%ok()) call cmd%get_text('NOM_PARA', para, st)
        if (st%failed()) return
        kind = TESTED_REAL
        if (cmd%has('VALE_CALC_I')) kind = TESTED_INT
        if (cmd%has('VALE_CALC_K')) kind = TESTED_TEXT
        if (kind /= TESTED_TEXT) then
            call read_checks(cmd%keyword_set_t, checks, integers, st)
            if (st%failed()) return
        end if
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
        call check_value_type(cmd, t, column, kind, st)
        if (st%failed()) return
        if (len(type_test) > 0) then
            call reduce_column(cmd, t, column, rows, type_test, value, st)
        else
            call single_cell(cmd, t, column, rows, value, st)
        end if
        if (st%failed()) return
        call add_column(cols, 'TABLE', concept_display_name(t))
        call add_column(cols, 'NOM_PARA', para)
        if (len(type_test) > 0) call add_column(cols, 'TYPE_TEST', type_test)
        select case (kind)
        case (TESTED_TEXT)
            call test_texts(ctx, cmd, cols, value%k, st)
        case (TESTED_INT)
            call write_test_block(ctx, cols, checks, real(value%i, dp), 'TEST_TABLE')
        case default
            call write_test_block(ctx, cols, checks, value%r, 'TEST_TABLE')
        end select
    end subroutine run_test_table

    !> VALE_CALC_K (and VALE_REFE_K with REFERENCE): the cell's text equals one of them
    !> (without surrounding blanks), as Code_Aster's tresu_str.
    subroutine test_texts(ctx, cmd, cols, computed, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(test_columns_t), intent(in) :: cols
        character(len=*), intent(in) :: computed
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: calc(:), refe(:), lines(:)
        character(len=:), allocatable :: kind, legend, id
        integer :: k
        call cmd%get_texts('VALE_CALC_K', calc, st)
        if (st%failed()) return
        legend = ''
        if (cmd%has('LEGENDE')) call cmd%get_text('LEGENDE', legend, st)
        if (st%failed()) return
        if (cmd%has('REFERENCE') .neqv. cmd%has('VALE_REFE_K')) then
            call cmd%error_at(trim(merge('REFERENCE  ', 'VALE_REFE_K', cmd%has('REFERENCE'))), &
                'REFERENCE and VALE_REFE_K go together (give both or neither)', st)
            return
        end if
        allocate (lines(merge(5, 4, cmd%has('REFERENCE'))))
        lines(1)%s = ' ---- ' // pad(17, cols%titles(1)%s) // pad(17, cols%titles(2)%s)
        lines(2)%s = repeat(' ', 6) // pad(17, cols%values(1)%s) // cols%values(2)%s
        lines(1)%s = trim(lines(1)%s)
        lines(3)%s = test_resu_header_line()
        lines(4)%s = text_check_line('NON_REGRESSION', '', calc, computed)
        if (cmd%has('REFERENCE')) then
            call cmd%get_text('REFERENCE', kind, st)
            if (st%ok()) call cmd%get_texts('VALE_REFE_K', refe, st)
            if (st%failed()) return
            lines(5)%s = text_check_line(kind, legend, refe, computed)
        end if
        do k = 1, size(lines)
            call ctx%write_resu(listing_safe_text(lines(k)%s))
        end do
        id = compact_text(lines(2)%s)
        do k = 4, size(lines)
            call ctx%count_test(lines(k)%s(1:4) == ' OK ')
            call ctx%write_mess('    TEST_TABLE ' // id // ': ' // &
                                listing_safe_text(compact_text(lines(k)%s)))
        end do
    end subroutine test_texts

    !> One check line of texts (TEST_TABLE VALE_CALC_K, TEST_FONCTION ATTRIBUT): OK when
    !> the computed text equals one of the expected ones (without surrounding blanks).
    function text_check_line(kind, legend, expected, computed) result(line)
        character(len=*), intent(in) :: kind, legend, computed
        type(string_t), intent(in) :: expected(:)
        character(len=:), allocatable :: line, reference, shown_legend
        logical :: ok
        integer :: k
        reference = trim(adjustl(expected(1)%s))
        ok = .false.
        do k = 1, size(expected)
            if (trim(adjustl(expected(k)%s)) == trim(adjustl(computed))) then
                ok = .true.
                reference = trim(adjustl(expected(k)%s))
            end if
        end do
        shown_legend = legend
        if (len_trim(legend) == 0) shown_legend = TEST_RESU_NO_LEGEND
        line = merge(' OK   ', 'NOOK  ', ok) // pad(17, kind) // pad(17, shown_legend) // &
            pad(24, '''' // reference // '''') // &
            pad(24, '''' // trim(adjustl(computed)) // '''') // pad(16, '-') // '-'
    end function text_check_line

    pure function pad(width, text) result(out)
        integer, intent(in) :: width
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: out
        out = text // repeat(' ', max(1, width - len(text)))
    end function pad

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
            ' values: test it with ' // trim(merge('VALE_CALC_I', 'VALE_CALC  ', &
            wanted == TESTED_INT)) // trim(merge('_K', '  ', wanted == TESTED_TEXT)), st)
    end subroutine check_value_type

    !> The one cell the filters leave: among the rows they select, those holding a value of
    !> NOM_PARA must be exactly one, as Code_Aster's tbliva counts them (a POST_RELEVE_T
    !> table's rows of another ACTION, without that column's value, do not count).
    subroutine single_cell(cmd, t, column, rows, value, st)
        type(command_t), intent(in) :: cmd
        type(table_t), intent(in) :: t
        integer, intent(in) :: column
        integer, intent(in) :: rows(:)
        type(tested_value_t), intent(out) :: value
        type(status_t), intent(inout) :: st
        type(keyword_set_t) :: occ
        integer, allocatable :: held(:)
        held = pack(rows, t%columns(column)%present(rows))
        if (size(held) == 0) then
            call cmd%error_at('NOM_PARA', 'the cell of column ' // t%columns(column)%name // &
                ' is empty in the ' // to_text(int(size(rows), i4)) // ' row(s) the ' // &
                'filters select', st, STATUS_MODEL_ERROR)
            return
        end if
        if (size(held) /= 1) then
            occ = cmd%keyword_set_t
            if (cmd%count('FILTRE') > 0) occ = cmd%occurrence('FILTRE', cmd%count('FILTRE'))
            call occ%error_at('', to_text(int(size(held), i4)) // ' rows of table ' // &
                concept_display_name(t) // ' pass the filters with a value of ' // &
                t%columns(column)%name // ': TEST_TABLE tests one cell ' // &
                '(add a FILTRE, or give TYPE_TEST); ' // t%columns(column)%name // &
                ' in those rows: ' // column_values_text(t, column, held), st, &
                STATUS_MODEL_ERROR)
            return
        end if
        call cell_value(t, column, held(1), value)
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
