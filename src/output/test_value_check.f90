!> The checks of TEST_TABLE and TEST_FONCTION: one computed value against the deck's
!> VALE_CALC (NON_REGRESSION, within TOLE_MACHINE) and, with REFERENCE, VALE_REFE (within
!> PRECISION), as Code_Aster's tresu_print and TestResult.showResult judge them:
!>  - several VALE_CALC (or VALE_REFE) values: the one closest to the computed value is
!>    taken;
!>  - VALE_ABS='OUI': absolute values of both sides are compared (and printed);
!>  - a VALE_CALC of 0 (|v| <= 2**-52, Code_Aster's r8prem) without ORDRE_GRANDEUR: the
!>    non-regression check is skipped (a SKIP line, counted neither OK nor NOOK: a zero
!>    computed by round-off cannot be reproduced); with ORDRE_GRANDEUR g and CRITERE
!>    'ABSOLU' the tolerance becomes TOLE_MACHINE*g (an "ORDRE DE GRANDEUR" line says so);
!>  - integers compare as numbers; texts are equal or not.
!> Lines follow listings.md's TEST_RESU block (test_resu_format): identification lines,
!> the header, then ` OK  `, `NOOK ` or `SKIP ` lines.
module test_value_check
    use kinds, only: dp, i4, i8
    use strings, only: string_t, to_text, real_e13, real_short
    use status, only: status_t
    use deck_command, only: keyword_set_t
    use run_context, only: run_context_t
    use test_resu_command, only: listing_safe_text, compact_text
    use test_resu_format, only: test_resu_header_line, test_resu_check_line, &
        test_resu_passes, TEST_RESU_NO_LEGEND
    implicit none
    private

    !> Kinds of tested values.
    integer, parameter, public :: TESTED_REAL = 1, TESTED_INT = 2, TESTED_TEXT = 3
    !> A VALE_CALC at most this large in magnitude is zero (Code_Aster's r8prem, 2**-52).
    real(dp), parameter, public :: TEST_ZERO = epsilon(1.0_dp)
    !> Column widths, as test_resu_format's.
    integer, parameter :: PREFIX_WIDTH = 6, ID_WIDTH = 17, KIND_WIDTH = 17, &
        LEGEND_WIDTH = 17, VALUE_WIDTH = 24, ERROR_WIDTH = 16

    !> What a TEST_* occurrence asks: the expected values and how to compare.
    type, public :: test_request_t
        integer :: kind = TESTED_REAL
        real(dp), allocatable :: calc_reals(:), refe_reals(:)
        integer(i8), allocatable :: calc_ints(:), refe_ints(:)
        type(string_t), allocatable :: calc_texts(:), refe_texts(:)
        logical :: has_reference = .false.
        character(len=:), allocatable :: reference_kind     !< ANALYTIQUE ...
        real(dp) :: tole_machine = 1.0e-6_dp, precision = 1.0e-3_dp
        character(len=:), allocatable :: criterion          !< RELATIF or ABSOLU
        logical :: absolute_values = .false.                !< VALE_ABS='OUI'
        character(len=:), allocatable :: legend
        logical :: has_magnitude = .false.
        real(dp) :: magnitude = 1.0_dp                      !< ORDRE_GRANDEUR
    end type test_request_t

    !> The computed value.
    type, public :: tested_value_t
        integer :: kind = TESTED_REAL
        real(dp) :: r = 0.0_dp
        integer(i8) :: i = 0
        character(len=:), allocatable :: k
    end type tested_value_t

    public :: read_test_request, test_check_lines, id_line_pair, tested_kind_name, &
        write_test_block

contains

    !> Reads VALE_CALC(_I/_K), VALE_REFE(_I/_K), REFERENCE, PRECISION, TOLE_MACHINE,
    !> CRITERE, VALE_ABS, LEGENDE, ORDRE_GRANDEUR from a keyword set.
    !>  st : located at VALE_REFE / REFERENCE when one is given without the other, or when
    !>       VALE_REFE is of another type or count than VALE_CALC
    subroutine read_test_request(set, req, st)
        class(keyword_set_t), intent(in) :: set
        type(test_request_t), intent(out) :: req
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: ints(:)
        character(len=:), allocatable :: text
        integer :: n_calc, n_refe
        if (set%has('VALE_CALC_I')) then
            req%kind = TESTED_INT
            call set%get_ints('VALE_CALC_I', ints, st)
            req%calc_ints = int(ints, i8)
        else if (set%has('VALE_CALC_K')) then
            req%kind = TESTED_TEXT
            call set%get_texts('VALE_CALC_K', req%calc_texts, st)
        else
            req%kind = TESTED_REAL
            call set%get_reals('VALE_CALC', req%calc_reals, st)
        end if
        if (st%failed()) return
        call set%get_real('TOLE_MACHINE', req%tole_machine, st)
        if (st%ok()) call set%get_text('CRITERE', req%criterion, st)
        if (st%ok() .and. set%has('VALE_ABS')) call set%get_text('VALE_ABS', text, st)
        if (st%failed()) return
        if (allocated(text)) req%absolute_values = text == 'OUI'
        req%legend = ''
        if (set%has('LEGENDE')) call set%get_text('LEGENDE', req%legend, st)
        if (st%ok() .and. set%has('ORDRE_GRANDEUR')) then
            req%has_magnitude = .true.
            call set%get_real('ORDRE_GRANDEUR', req%magnitude, st)
        end if
        if (st%failed()) return
        n_refe = count([set%has('VALE_REFE'), set%has('VALE_REFE_I'), set%has('VALE_REFE_K')])
        req%has_reference = set%has('REFERENCE')
        if (req%has_reference .neqv. n_refe > 0) then
            if (req%has_reference) then
                call set%error_at('REFERENCE', 'REFERENCE needs its value: give VALE_REFE' // &
                    trim(kind_suffix(req%kind)), st)
            else
                call set%error_at(refe_key(req%kind), 'VALE_REFE goes with REFERENCE ' // &
                    '(ANALYTIQUE, SOURCE_EXTERNE, AUTRE_ASTER or NON_DEFINI)', st)
            end if
            return
        end if
        if (.not. req%has_reference) return
        call set%get_text('REFERENCE', req%reference_kind, st)
        if (st%ok()) call set%get_real('PRECISION', req%precision, st)
        if (st%failed()) return
        if (.not. set%has(refe_key(req%kind))) then
            call set%error_at('REFERENCE', 'the reference must have the type of the ' // &
                'non-regression value: give ' // refe_key(req%kind) // ' with VALE_CALC' // &
                trim(kind_suffix(req%kind)), st)
            return
        end if
        select case (req%kind)
        case (TESTED_INT)
            call set%get_ints('VALE_REFE_I', ints, st)
            req%refe_ints = int(ints, i8)
            n_refe = size(ints)
            n_calc = size(req%calc_ints)
        case (TESTED_TEXT)
            call set%get_texts('VALE_REFE_K', req%refe_texts, st)
            n_refe = size(req%refe_texts)
            n_calc = size(req%calc_texts)
        case default
            call set%get_reals('VALE_REFE', req%refe_reals, st)
            n_refe = size(req%refe_reals)
            n_calc = size(req%calc_reals)
        end select
        if (st%failed()) return
        if (n_refe /= n_calc) call set%error_at(refe_key(req%kind), 'VALE_REFE' // &
            trim(kind_suffix(req%kind)) // ' has ' // to_text(int(n_refe, i4)) // &
            ' values but VALE_CALC' // trim(kind_suffix(req%kind)) // ' has ' // &
            to_text(int(n_calc, i4)) // ' (one reference per non-regression value)', st)
    end subroutine read_test_request

    pure function kind_suffix(kind) result(s)
        integer, intent(in) :: kind
        character(len=2) :: s
        s = ''
        if (kind == TESTED_INT) s = '_I'
        if (kind == TESTED_TEXT) s = '_K'
    end function kind_suffix

    pure function refe_key(kind) result(key)
        integer, intent(in) :: kind
        character(len=:), allocatable :: key
        key = 'VALE_REFE' // trim(kind_suffix(kind))
    end function refe_key

    !> 'reals', 'integers', 'texts' (for messages).
    pure function tested_kind_name(kind) result(name)
        integer, intent(in) :: kind
        character(len=:), allocatable :: name
        select case (kind)
        case (TESTED_INT)
            name = 'integers (VALE_CALC_I)'
        case (TESTED_TEXT)
            name = 'texts (VALE_CALC_K)'
        case default
            name = 'reals (VALE_CALC)'
        end select
    end function tested_kind_name

    !> The two identification lines: ` ---- ` + titles and 6 blanks + values, 17 wide.
    pure subroutine id_line_pair(titles, values, lines)
        type(string_t), intent(in) :: titles(:), values(:)
        type(string_t), intent(out) :: lines(2)
        integer :: k
        lines(1)%s = ' ---- '
        lines(2)%s = repeat(' ', PREFIX_WIDTH)
        do k = 1, size(titles)
            if (k < size(titles)) then
                lines(1)%s = lines(1)%s // pad(ID_WIDTH, titles(k)%s)
                lines(2)%s = lines(2)%s // pad(ID_WIDTH, values(k)%s)
            else
                lines(1)%s = lines(1)%s // titles(k)%s
                lines(2)%s = lines(2)%s // values(k)%s
            end if
        end do
    end subroutine id_line_pair

    !> The check lines of one tested value: [ORDRE DE GRANDEUR line,] header, the
    !> NON_REGRESSION line and, with a reference, the reference line.
    !>  lines : out;  n_ok, n_nook : inout, incremented by the verdicts (SKIP counts in
    !>          neither)
    subroutine test_check_lines(req, value, lines, n_ok, n_nook)
        type(test_request_t), intent(in) :: req
        type(tested_value_t), intent(in) :: value
        type(string_t), allocatable, intent(out) :: lines(:)
        integer, intent(inout) :: n_ok, n_nook
        type(string_t) :: line
        logical :: skip, ok
        real(dp) :: tolerance
        integer :: verdict
        allocate (lines(0))
        skip = .false.
        tolerance = req%tole_machine
        if (req%kind == TESTED_REAL) then
            if (abs(closest_real(req%calc_reals, value%r, req%absolute_values)) <= TEST_ZERO) then
                skip = .not. req%has_magnitude
                if (req%has_magnitude .and. req%criterion == 'ABSOLU') then
                    tolerance = abs(req%tole_machine * req%magnitude)
                    line%s = repeat(' ', PREFIX_WIDTH) // pad(KIND_WIDTH, 'ORDRE DE GRANDEUR :') &
                        // real_short(req%magnitude)
                    call push(lines, line)
                end if
            end if
        end if
        line%s = test_resu_header_line()
        call push(lines, line)
        call one_line('NON_REGRESSION', req%calc_reals, req%calc_ints, req%calc_texts, &
                      tolerance, skip, line, verdict)
        call push(lines, line)
        call count_verdict(verdict)
        if (.not. req%has_reference) return
        call one_line(req%reference_kind, req%refe_reals, req%refe_ints, req%refe_texts, &
                      req%precision, .false., line, verdict)
        call push(lines, line)
        call count_verdict(verdict)
    contains
        subroutine count_verdict(v)
            integer, intent(in) :: v
            if (v > 0) n_ok = n_ok + 1
            if (v < 0) n_nook = n_nook + 1
        end subroutine count_verdict

        !> verdict: 1 OK, -1 NOOK, 0 SKIP.
        subroutine one_line(kind, reals, ints, texts, tol, skipped, out, v)
            character(len=*), intent(in) :: kind
            real(dp), allocatable, intent(in) :: reals(:)
            integer(i8), allocatable, intent(in) :: ints(:)
            type(string_t), allocatable, intent(in) :: texts(:)
            real(dp), intent(in) :: tol
            logical, intent(in) :: skipped
            type(string_t), intent(out) :: out
            integer, intent(out) :: v
            real(dp) :: ref, val
            integer(i8) :: iref, ival
            character(len=:), allocatable :: legend, kref, kval
            legend = req%legend
            if (len_trim(legend) == 0) legend = TEST_RESU_NO_LEGEND
            select case (req%kind)
            case (TESTED_REAL)
                val = value%r
                if (req%absolute_values) val = abs(val)
                ref = closest_real(reals, value%r, req%absolute_values)
                if (skipped) then
                    out%s = 'SKIP  ' // pad(KIND_WIDTH, kind) // pad(LEGEND_WIDTH, legend) // &
                        pad(VALUE_WIDTH, real_e13(ref)) // pad(VALUE_WIDTH, real_e13(val)) // &
                        pad(ERROR_WIDTH, '-') // '-'
                    v = 0
                    return
                end if
                call test_resu_check_line(kind, req%legend, ref, val, tol, req%criterion, &
                                          out%s, ok)
            case (TESTED_INT)
                ival = value%i
                if (req%absolute_values) ival = abs(ival)
                iref = closest_int(ints, value%i, req%absolute_values)
                call int_line(kind, legend, iref, ival, tol, out%s, ok)
            case default
                kval = trim(adjustl(value%k))
                kref = closest_text(texts, kval)
                ok = kref == kval
                out%s = verdict_prefix(ok) // pad(KIND_WIDTH, kind) // pad(LEGEND_WIDTH, legend) // &
                    pad(VALUE_WIDTH, '''' // kref // '''') // &
                    pad(VALUE_WIDTH, '''' // kval // '''') // pad(ERROR_WIDTH, '-') // '-'
            end select
            v = merge(1, -1, ok)
        end subroutine one_line

        subroutine int_line(kind, legend, iref, ival, tol, text, passed)
            character(len=*), intent(in) :: kind, legend
            integer(i8), intent(in) :: iref, ival
            real(dp), intent(in) :: tol
            character(len=:), allocatable, intent(out) :: text
            logical, intent(out) :: passed
            character(len=:), allocatable :: error_text, tol_text
            real(dp) :: difference
            passed = test_resu_passes(real(iref, dp), real(ival, dp), tol, req%criterion)
            difference = abs(real(iref, dp) - real(ival, dp))
            if (req%criterion == 'ABSOLU') then
                error_text = to_text(abs(iref - ival))
                tol_text = real_short(tol)
            else
                if (iref /= 0) then
                    error_text = real_short(100.0_dp * difference / abs(real(iref, dp))) // '%'
                else if (ival == 0) then
                    error_text = real_short(0.0_dp) // '%'
                else
                    error_text = '+Inf%'
                end if
                tol_text = real_short(100.0_dp * tol) // '%'
            end if
            text = verdict_prefix(passed) // pad(KIND_WIDTH, kind) // pad(LEGEND_WIDTH, legend) // &
                pad(VALUE_WIDTH, to_text(iref)) // pad(VALUE_WIDTH, to_text(ival)) // &
                pad(ERROR_WIDTH, error_text) // tol_text
        end subroutine int_line
    end subroutine test_check_lines

    !> Writes a block (identification lines, then check lines) to the .resu, echoes each
    !> verdict line compactly to the .mess after `label` (e.g. 'TEST_TABLE') and counts the
    !> OK and NOOK lines in the run context (NOOK makes the run exit with status 2).
    subroutine write_test_block(ctx, label, id_lines, check_lines)
        type(run_context_t), intent(inout) :: ctx
        character(len=*), intent(in) :: label
        type(string_t), intent(in) :: id_lines(:), check_lines(:)
        integer :: k
        character(len=:), allocatable :: id
        do k = 1, size(id_lines)
            call ctx%write_resu(listing_safe_text(id_lines(k)%s))
        end do
        do k = 1, size(check_lines)
            call ctx%write_resu(listing_safe_text(check_lines(k)%s))
        end do
        id = compact_text(id_lines(size(id_lines))%s)
        do k = 1, size(check_lines)
            if (len(check_lines(k)%s) < 4) cycle
            select case (check_lines(k)%s(1:4))
            case (' OK ', 'NOOK')
                call ctx%count_test(check_lines(k)%s(1:4) == ' OK ')
            case ('SKIP')
            case default
                cycle
            end select
            call ctx%write_mess('    ' // label // ' ' // id // ': ' // &
                                listing_safe_text(compact_text(check_lines(k)%s)))
        end do
    end subroutine write_test_block

    !> ' OK   ' or 'NOOK  ' (listings.md).
    pure function verdict_prefix(ok) result(text)
        logical, intent(in) :: ok
        character(len=6) :: text
        text = 'NOOK  '
        if (ok) text = ' OK   '
    end function verdict_prefix

    !> The expected value closest to `computed` (absolute values with `absolute`); 0 when
    !> there is none.
    pure real(dp) function closest_real(values, computed, absolute) result(best)
        real(dp), allocatable, intent(in) :: values(:)
        real(dp), intent(in) :: computed
        logical, intent(in) :: absolute
        real(dp) :: v, c
        integer :: k
        best = 0.0_dp
        if (.not. allocated(values)) return
        if (size(values) == 0) return
        c = computed
        if (absolute) c = abs(c)
        best = values(1)
        if (absolute) best = abs(best)
        do k = 2, size(values)
            v = values(k)
            if (absolute) v = abs(v)
            if (abs(v - c) < abs(best - c)) best = v
        end do
    end function closest_real

    pure integer(i8) function closest_int(values, computed, absolute) result(best)
        integer(i8), allocatable, intent(in) :: values(:)
        integer(i8), intent(in) :: computed
        logical, intent(in) :: absolute
        integer(i8) :: v, c
        integer :: k
        best = 0
        if (.not. allocated(values)) return
        if (size(values) == 0) return
        c = computed
        if (absolute) c = abs(c)
        best = values(1)
        if (absolute) best = abs(best)
        do k = 2, size(values)
            v = values(k)
            if (absolute) v = abs(v)
            if (abs(v - c) < abs(best - c)) best = v
        end do
    end function closest_int

    !> The expected text equal to `computed` if any, else the first.
    pure function closest_text(values, computed) result(best)
        type(string_t), allocatable, intent(in) :: values(:)
        character(len=*), intent(in) :: computed
        character(len=:), allocatable :: best
        integer :: k
        best = ''
        if (.not. allocated(values)) return
        if (size(values) == 0) return
        best = trim(adjustl(values(1)%s))
        do k = 1, size(values)
            if (trim(adjustl(values(k)%s)) == computed) best = computed
        end do
    end function closest_text

    subroutine push(lines, line)
        type(string_t), allocatable, intent(inout) :: lines(:)
        type(string_t), intent(in) :: line
        type(string_t), allocatable :: bigger(:)
        integer :: k
        allocate (bigger(size(lines) + 1))
        do k = 1, size(lines)
            call move_alloc(lines(k)%s, bigger(k)%s)
        end do
        bigger(size(bigger))%s = line%s
        call move_alloc(bigger, lines)
    end subroutine push

    !> `text` left-aligned in `width` columns, or followed by one blank when longer.
    pure function pad(width, text) result(out)
        integer, intent(in) :: width
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: out
        out = text // repeat(' ', max(1, width - len(text)))
    end function pad

end module test_value_check
