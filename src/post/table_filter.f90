!> Row filters of tables (FILTRE of TEST_TABLE, IMPR_TABLE, RECU_FONCTION, CALC_TABLE
!> OPERATION='FILTRE'): CRIT_COMP EQ, NE, LT, GT, LE, GE against VALE / VALE_I / VALE_K
!> (one value or several), VIDE, NON_VIDE, MAXI, MAXI_ABS, MINI, MINI_ABS and REGEXP.
!>
!> Code_Aster has two implementations and parasol follows each where it is used:
!>  - the Python one (Table.Colonne: CALC_TABLE, IMPR_TABLE, RECU_FONCTION): EQ keeps a
!>    real within PRECISION of one of the values, relative to that value (CRITERE
!>    'RELATIF') or absolute; NE keeps the others, absent cells included; MAXI/MINI keep
!>    every row holding the extreme value;
!>  - the Fortran one (tbextb: TEST_TABLE), `cell_relative`: the relative precision of EQ
!>    and NE is taken on the cell's value, absent cells never match, MAXI/MINI keep the
!>    first row holding the extreme value.
!> In both, integers compare exactly, texts compare without leading and trailing blanks,
!> LT/LE compare with the largest of several values and GT/GE with the smallest.
!> A number against a text column (or the reverse) is a type mismatch, reported.
module table_filter
    use kinds, only: dp, i4, i8
    use strings, only: string_t, to_text
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use deck_concept, only: concept_display_name
    use table_concept, only: table_t, table_column_t, TABLE_INT, TABLE_REAL, TABLE_TEXT, table_kind_label, &
        table_require_column
    use table_sort, only: compare_texts
    use text_pattern, only: pattern_t, compile_pattern, pattern_search
    implicit none
    private

    !> Kinds of filter values.
    integer, parameter, public :: FILTER_NO_VALUE = 0, FILTER_INTS = TABLE_INT, &
        FILTER_REALS = TABLE_REAL, FILTER_TEXTS = TABLE_TEXT

    !> One filter: column NOM_PARA, operation CRIT_COMP, its values.
    type, public :: table_filter_t
        character(len=:), allocatable :: column
        character(len=:), allocatable :: operation       !< EQ, NE, LT, ... REGEXP
        integer :: value_kind = FILTER_NO_VALUE
        integer(i8), allocatable :: ints(:)
        real(dp), allocatable :: reals(:)
        type(string_t), allocatable :: texts(:)
        logical :: absolute = .false.                   !< CRITERE='ABSOLU'
        real(dp) :: precision = 0.0_dp                   !< PRECISION
        logical :: cell_relative = .false.               !< TEST_TABLE's rules (above)
    end type table_filter_t

    public :: apply_table_filter, describe_filter

contains

    !> Keeps the rows of `rows` that pass filter `f` (order kept).
    !>  t    : in, the table
    !>  rows : inout, row indices of t; on return those that pass
    !>  st   : STATUS_MODEL_ERROR when the column does not exist (naming those that do), the
    !>         filter's values do not match the column's type, or a REGEXP is not valid
    subroutine apply_table_filter(t, f, rows, st)
        type(table_t), intent(in) :: t
        type(table_filter_t), intent(in) :: f
        integer, allocatable, intent(inout) :: rows(:)
        type(status_t), intent(inout) :: st
        integer :: column
        logical, allocatable :: keep(:)
        call table_require_column(t, f%column, column, st)
        if (st%failed()) return
        call check_types(t, column, f, st)
        if (st%failed()) return
        allocate (keep(size(rows)))
        select case (f%operation)
        case ('VIDE')
            keep = .not. t%columns(column)%present(rows)
        case ('NON_VIDE')
            keep = t%columns(column)%present(rows)
        case ('MAXI', 'MINI', 'MAXI_ABS', 'MINI_ABS')
            call extreme_rows(t%columns(column), rows, f, keep)
        case ('REGEXP')
            call regexp_rows(t, column, rows, f, keep, st)
            if (st%failed()) return
        case default
            call compare_rows(t%columns(column), rows, f, keep)
        end select
        rows = pack(rows, keep)
    end subroutine apply_table_filter

    !> The filter in words, as Code_Aster traces it in a title:
    !> `NOM_PARA: INST CRIT_COMP: EQ VALE: 1.0`.
    function describe_filter(f) result(text)
        type(table_filter_t), intent(in) :: f
        character(len=:), allocatable :: text
        integer :: k
        text = 'NOM_PARA: ' // f%column // ' CRIT_COMP: ' // f%operation
        select case (f%value_kind)
        case (FILTER_INTS)
            text = text // ' VALE_I:'
            do k = 1, size(f%ints)
                text = text // ' ' // to_text(f%ints(k))
            end do
        case (FILTER_REALS)
            text = text // ' VALE:'
            do k = 1, size(f%reals)
                text = text // ' ' // to_text(f%reals(k))
            end do
        case (FILTER_TEXTS)
            text = text // ' VALE_K:'
            do k = 1, size(f%texts)
                text = text // ' ''' // f%texts(k)%s // ''''
            end do
        end select
    end function describe_filter

    !> Numbers go with numeric columns, texts with text columns; comparisons need a value.
    subroutine check_types(t, column, f, st)
        type(table_t), intent(in) :: t
        integer, intent(in) :: column
        type(table_filter_t), intent(in) :: f
        type(status_t), intent(inout) :: st
        logical :: text_column
        select case (f%operation)
        case ('VIDE', 'NON_VIDE')
            return
        case ('MAXI', 'MINI', 'MAXI_ABS', 'MINI_ABS')
            if (t%columns(column)%kind /= TABLE_TEXT) return
            call set_error(st, STATUS_MODEL_ERROR, 'CRIT_COMP=''' // f%operation // &
                ''' needs a numeric column: ' // f%column // ' of table ' // &
                concept_display_name(t) // ' holds texts (' // &
                table_kind_label(t%columns(column)) // ')')
            return
        case ('REGEXP')
            if (t%columns(column)%kind == TABLE_TEXT .and. f%value_kind == FILTER_TEXTS) return
            call set_error(st, STATUS_MODEL_ERROR, 'CRIT_COMP=''REGEXP'' needs a text ' // &
                'column and VALE_K: ' // f%column // ' holds ' // &
                table_kind_label(t%columns(column)))
            return
        end select
        if (f%value_kind == FILTER_NO_VALUE) then
            call set_error(st, STATUS_MODEL_ERROR, 'CRIT_COMP=''' // f%operation // &
                ''' compares with a value: give VALE, VALE_I or VALE_K')
            return
        end if
        text_column = t%columns(column)%kind == TABLE_TEXT
        if (text_column .eqv. (f%value_kind == FILTER_TEXTS)) return
        if (text_column) then
            call set_error(st, STATUS_MODEL_ERROR, 'column ' // f%column // ' of table ' // &
                concept_display_name(t) // ' holds texts (' // &
                table_kind_label(t%columns(column)) // '): filter it with VALE_K, not ' // &
                trim(merge('VALE_I', 'VALE  ', f%value_kind == FILTER_INTS)))
        else
            call set_error(st, STATUS_MODEL_ERROR, 'column ' // f%column // ' of table ' // &
                concept_display_name(t) // ' holds numbers (' // &
                table_kind_label(t%columns(column)) // '): filter it with ' // &
                trim(merge('VALE_I', 'VALE  ', t%columns(column)%kind == TABLE_INT)) // &
                ', not VALE_K')
        end if
    end subroutine check_types

    !> EQ, NE, LT, GT, LE, GE.
    subroutine compare_rows(col, rows, f, keep)
        type(table_column_t), intent(in) :: col
        integer, intent(in) :: rows(:)
        type(table_filter_t), intent(in) :: f
        logical, intent(out) :: keep(:)
        integer :: k, r
        do k = 1, size(rows)
            r = rows(k)
            if (.not. col%present(r)) then
                ! an absent cell is "not equal" for the Python filters only
                keep(k) = f%operation == 'NE' .and. .not. f%cell_relative
                cycle
            end if
            select case (col%kind)
            case (TABLE_TEXT)
                keep(k) = text_passes(col%texts(r)%s, f)
            case (TABLE_INT)
                keep(k) = number_passes(real(col%ints(r), dp), col%ints(r), .true., f)
            case default
                keep(k) = number_passes(col%reals(r), 0_i8, .false., f)
            end select
        end do
    end subroutine compare_rows

    !> Whether a text cell passes (values compared without surrounding blanks).
    logical function text_passes(cell, f) result(ok)
        character(len=*), intent(in) :: cell
        type(table_filter_t), intent(in) :: f
        integer :: k, c
        character(len=:), allocatable :: value
        value = trim(adjustl(cell))
        select case (f%operation)
        case ('EQ', 'NE')
            ok = .false.
            do k = 1, size(f%texts)
                if (value == trim(adjustl(f%texts(k)%s)) .and. &
                    len(value) == len_trim(adjustl(f%texts(k)%s))) ok = .true.
            end do
            if (f%operation == 'NE') ok = .not. ok
        case default
            ! LT/LE against the largest value, GT/GE against the smallest
            c = 1
            do k = 2, size(f%texts)
                if (compare_texts(f%texts(k)%s, f%texts(c)%s) > 0 .eqv. &
                    (f%operation == 'LT' .or. f%operation == 'LE')) c = k
            end do
            k = compare_texts(value, f%texts(c)%s)
            select case (f%operation)
            case ('LT')
                ok = k < 0
            case ('LE')
                ok = k <= 0
            case ('GT')
                ok = k > 0
            case default
                ok = k >= 0
            end select
        end select
    end function text_passes

    !> Whether a numeric cell passes.
    !>  x : the cell as a real;  i, is_int : the cell as an integer when it is one
    logical function number_passes(x, i, is_int, f) result(ok)
        real(dp), intent(in) :: x
        integer(i8), intent(in) :: i
        logical, intent(in) :: is_int
        type(table_filter_t), intent(in) :: f
        real(dp), allocatable :: values(:)
        integer :: k
        if (f%value_kind == FILTER_INTS) then
            values = real(f%ints, dp)
        else
            values = f%reals
        end if
        select case (f%operation)
        case ('EQ', 'NE')
            ok = .false.
            do k = 1, size(values)
                if (f%value_kind == FILTER_INTS .and. is_int) then
                    if (i == f%ints(k)) ok = .true.          ! integers: exactly
                else if (equal_within(x, values(k), f)) then
                    ok = .true.
                end if
            end do
            if (f%operation == 'NE') ok = .not. ok
        case ('LT')
            ok = x < maxval(values)
        case ('LE')
            ok = x <= maxval(values)
        case ('GT')
            ok = x > minval(values)
        case default
            ok = x >= minval(values)
        end select
    end function number_passes

    !> x equal to value within the filter's PRECISION (0: exactly).
    !> Formed in halves so that no difference or product overflows, whatever finite numbers
    !> the table and the deck hold (|x - v| <= p |r|  <=>  |x/2 - v/2| <= (p |r|)/2, and for
    !> p > 1  <=>  |x/2 - v/2| / p <= |r|/2): the same answer as the plain test wherever
    !> that one is finite.
    pure logical function equal_within(x, value, f)
        real(dp), intent(in) :: x, value
        type(table_filter_t), intent(in) :: f
        real(dp) :: half_difference, reference
        if (f%precision <= 0.0_dp) then
            equal_within = .not. (x < value .or. x > value)
            return
        end if
        half_difference = abs(0.5_dp * x - 0.5_dp * value)
        if (f%absolute) then
            equal_within = half_difference <= 0.5_dp * f%precision
            return
        end if
        reference = abs(value)
        if (f%cell_relative) reference = abs(x)
        if (f%precision <= 1.0_dp) then
            equal_within = half_difference <= 0.5_dp * (f%precision * reference)
        else
            equal_within = half_difference / f%precision <= 0.5_dp * reference
        end if
    end function equal_within

    !> MAXI, MINI, MAXI_ABS, MINI_ABS over the present cells of the selection.
    subroutine extreme_rows(col, rows, f, keep)
        type(table_column_t), intent(in) :: col
        integer, intent(in) :: rows(:)
        type(table_filter_t), intent(in) :: f
        logical, intent(out) :: keep(:)
        real(dp) :: best, v
        integer :: k, first
        logical :: found, absolute, largest
        keep = .false.
        absolute = f%operation == 'MAXI_ABS' .or. f%operation == 'MINI_ABS'
        largest = f%operation == 'MAXI' .or. f%operation == 'MAXI_ABS'
        found = .false.
        best = 0.0_dp
        first = 0
        do k = 1, size(rows)
            if (.not. col%present(rows(k))) cycle
            v = cell_value(col, rows(k), absolute)
            if (.not. found) then
                best = v; found = .true.; first = k
            else if ((largest .and. v > best) .or. (.not. largest .and. v < best)) then
                best = v; first = k
            end if
        end do
        if (.not. found) return
        if (f%cell_relative) then
            keep(first) = .true.               ! TEST_TABLE: the first row only
            return
        end if
        do k = 1, size(rows)
            if (.not. col%present(rows(k))) cycle
            keep(k) = .not. (cell_value(col, rows(k), absolute) < best .or. &
                            cell_value(col, rows(k), absolute) > best)
        end do
    end subroutine extreme_rows

    pure real(dp) function cell_value(col, r, absolute)
        type(table_column_t), intent(in) :: col
        integer, intent(in) :: r
        logical, intent(in) :: absolute
        if (col%kind == TABLE_INT) then
            cell_value = real(col%ints(r), dp)
        else
            cell_value = col%reals(r)
        end if
        if (absolute) cell_value = abs(cell_value)
    end function cell_value

    !> REGEXP: rows whose text contains a match of the pattern (Python's re.search).
    subroutine regexp_rows(t, column, rows, f, keep, st)
        type(table_t), intent(in) :: t
        integer, intent(in) :: column
        integer, intent(in) :: rows(:)
        type(table_filter_t), intent(in) :: f
        logical, intent(out) :: keep(:)
        type(status_t), intent(inout) :: st
        type(pattern_t) :: pattern
        integer :: k
        keep = .false.
        call compile_pattern(f%texts(1)%s, pattern, st)
        if (st%failed()) return
        do k = 1, size(rows)
            if (.not. t%columns(column)%present(rows(k))) cycle
            keep(k) = pattern_search(pattern, t%columns(column)%texts(rows(k))%s)
        end do
    end subroutine regexp_rows

end module table_filter
