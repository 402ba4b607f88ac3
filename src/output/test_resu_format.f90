!> TEST_RESU lines of the `.resu` listing (listings.md, "TEST_RESU block"): identification
!> lines, the table header, the verdict of one check and its line, and the final tally.
!>
!> Layout (fixed-width fields, left-aligned, a field longer than its width is followed by one
!> blank so tokens never merge):
!>  ` ---- ` + 17-wide titles          RESULTAT NUME_ORDRE|INST NOM_CHAM NOM_CMP GROUP_NO|NOEUD
!>                                     (element fields: GROUP_MA|MAILLE, then POINT)
!>  6 blanks + 17-wide values
!>  6 blanks + REFERENCE(17) LEGENDE(17) VALE_REFE(24) VALE_CALC(24) ERREUR(16) TOLE
!>  ` OK   ` or `NOOK  ` + the same columns
!> Values are in E format with 13 significant digits (real_e13); error and tolerance with 3
!> significant digits, in percent for CRITERE='RELATIF', absolute for 'ABSOLU'.
module test_resu_format
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use kinds, only: dp
    use strings, only: string_t, real_e13, real_short, to_upper
    implicit none
    private

    !> Column widths of the listing (listings.md example).
    integer, parameter :: PREFIX_WIDTH = 6, ID_WIDTH = 17, KIND_WIDTH = 17, LEGEND_WIDTH = 17
    integer, parameter :: VALUE_WIDTH = 24, ERROR_WIDTH = 16
    !> The legend printed when the deck gives none (Code_Aster prints XXXX).
    character(len=*), parameter, public :: TEST_RESU_NO_LEGEND = 'XXXX'
    !> Printed as the error of a RELATIF check whose reference is 0 and value is not, or
    !> whose error is not a finite number.
    character(len=*), parameter :: INFINITE_ERROR = '+Inf'
    !> Default tolerance of the NON_REGRESSION check (Code_Aster TEST_RESU TOLE_MACHINE).
    real(dp), parameter, public :: TEST_RESU_DEFAULT_TOLE_MACHINE = 1.0e-6_dp
    !> Default tolerance of the reference check (Code_Aster TEST_RESU PRECISION).
    real(dp), parameter, public :: TEST_RESU_DEFAULT_PRECISION = 1.0e-3_dp

    public :: test_resu_id_lines, test_resu_header_line, test_resu_passes
    public :: test_resu_check_line, test_resu_summary_line, is_test_resu_criterion
    public :: test_resu_block_lines

    !> Verdicts of one check (test_check_line): OK, NOOK, or skipped (a NON_REGRESSION value
    !> below the machine epsilon without ORDRE_GRANDEUR, as Code_Aster skips it).
    integer, parameter, public :: CHECK_NOOK = 0, CHECK_OK = 1, CHECK_SKIP = -1
    !> The magnitude below which a VALE_CALC counts as zero (Code_Aster's r8prem).
    real(dp), parameter, public :: TEST_RESU_ZERO = epsilon(1.0_dp)

    !> One check of a tested value (TEST_RESU, listings.md "TEST_RESU semantics").
    !>  kind        NON_REGRESSION, ANALYTIQUE, AUTRE_ASTER, SOURCE_EXTERNE, NON_DEFINI
    !>  references  VALE_CALC (or VALE_REFE): the one closest to the value is used
    !>  tolerance   TOLE_MACHINE (or PRECISION), a fraction
    !>  criterion   RELATIF or ABSOLU
    !>  magnitude   ORDRE_GRANDEUR: the tolerance of an ABSOLU check is tolerance*magnitude
    !>  skip        the check is skipped (printed, not counted)
    !>  absolute_values  VALE_ABS='OUI': |value| is compared with |reference|
    !>  integers    integer values (VALE_CALC_I): printed as integers
    type, public :: test_check_t
        character(len=:), allocatable :: kind, legend, criterion
        real(dp), allocatable :: references(:)
        real(dp) :: tolerance = TEST_RESU_DEFAULT_TOLE_MACHINE
        real(dp) :: magnitude = 1.0_dp
        logical :: skip = .false.
        logical :: absolute_values = .false.
        logical :: integers = .false.
    end type test_check_t

    public :: test_resu_id_columns, test_check_line, test_check_block

contains

    !> The two identification lines of a TEST_RESU occurrence.
    !>  result_name    : in, the result concept (e.g. resu)
    !>  field_name     : in, NOM_CHAM (e.g. DEPL)
    !>  component      : in, NOM_CMP (e.g. DZ)
    !>  location_kind  : in, 'GROUP_NO' or 'NOEUD' (the heading of the last column)
    !>  location_name  : in, the group or node name (e.g. PT01)
    !>  nume_ordre     : in, optional, the NUME_ORDRE column when present
    !>  inst           : in, optional, the INST column when present (after NUME_ORDRE)
    !>  lines          : out, the two lines
    !>  point          : in, optional, the POINT column (element fields) after the location
    pure subroutine test_resu_id_lines(result_name, field_name, component, location_kind, &
                                       location_name, lines, nume_ordre, inst, point)
        character(len=*), intent(in) :: result_name, field_name, component, location_kind, &
                                        location_name
        type(string_t), intent(out) :: lines(2)
        integer, intent(in), optional :: nume_ordre, point
        real(dp), intent(in), optional :: inst
        character(len=12) :: buf
        lines(1)%s = ' ---- ' // field(ID_WIDTH, 'RESULTAT')
        lines(2)%s = repeat(' ', PREFIX_WIDTH) // field(ID_WIDTH, result_name)
        if (present(nume_ordre)) then
            write (buf, '(i0)') nume_ordre
            lines(1)%s = lines(1)%s // field(ID_WIDTH, 'NUME_ORDRE')
            lines(2)%s = lines(2)%s // field(ID_WIDTH, trim(buf))
        end if
        if (present(inst)) then
            lines(1)%s = lines(1)%s // field(ID_WIDTH + 4, 'INST')
            lines(2)%s = lines(2)%s // field(ID_WIDTH + 4, real_e13(inst))
        end if
        lines(1)%s = lines(1)%s // field(ID_WIDTH, 'NOM_CHAM') // field(ID_WIDTH, 'NOM_CMP')
        lines(2)%s = lines(2)%s // field(ID_WIDTH, field_name) // field(ID_WIDTH, component)
        if (present(point)) then
            write (buf, '(i0)') point
            lines(1)%s = lines(1)%s // field(ID_WIDTH, trim(location_kind)) // 'POINT'
            lines(2)%s = lines(2)%s // field(ID_WIDTH, trim(location_name)) // trim(buf)
        else
            lines(1)%s = lines(1)%s // trim(location_kind)
            lines(2)%s = lines(2)%s // trim(location_name)
        end if
    end subroutine test_resu_id_lines

    !> The two identification lines of a tested value from (title, value) columns: each
    !> column 17 wide (INST 21), the last one not padded (listings.md).
    pure subroutine test_resu_id_columns(titles, values, lines)
        type(string_t), intent(in) :: titles(:), values(:)
        type(string_t), intent(out) :: lines(2)
        integer :: k, width
        lines(1)%s = ' ---- '
        lines(2)%s = repeat(' ', PREFIX_WIDTH)
        do k = 1, size(titles)
            if (k == size(titles)) then
                lines(1)%s = lines(1)%s // trim(titles(k)%s)
                lines(2)%s = lines(2)%s // trim(values(k)%s)
            else
                width = ID_WIDTH
                if (titles(k)%s == 'INST') width = ID_WIDTH + 4
                lines(1)%s = lines(1)%s // field(width, titles(k)%s)
                lines(2)%s = lines(2)%s // field(width, values(k)%s)
            end if
        end do
    end subroutine test_resu_id_columns

    !> One check line for a computed value (see test_check_t): the reference closest to the
    !> value, the verdict, the error and the tolerance; a skipped check prints dashes.
    !>  verdict : out, CHECK_OK, CHECK_NOOK or CHECK_SKIP
    pure subroutine test_check_line(check, computed, line, verdict)
        type(test_check_t), intent(in) :: check
        real(dp), intent(in) :: computed
        character(len=:), allocatable, intent(out) :: line
        integer, intent(out) :: verdict
        real(dp) :: value, reference, tolerance
        character(len=:), allocatable :: legend, error_text, tolerance_text, ref_text, val_text
        logical :: ok
        integer :: k
        legend = ''
        if (allocated(check%legend)) legend = trim(check%legend)
        if (len(legend) == 0) legend = TEST_RESU_NO_LEGEND
        if (check%skip .or. size(check%references) == 0) then
            verdict = CHECK_SKIP
            line = 'SKIP  ' // field(KIND_WIDTH, check%kind) // field(LEGEND_WIDTH, '-') // &
                field(VALUE_WIDTH, '-') // field(VALUE_WIDTH, '-') // field(ERROR_WIDTH, '-') &
                // '-'
            return
        end if
        value = computed
        if (check%absolute_values) value = abs(value)
        reference = check%references(1)
        if (check%absolute_values) reference = abs(reference)
        do k = 2, size(check%references)
            if (abs(value - merge(abs(check%references(k)), check%references(k), &
                check%absolute_values)) < abs(value - reference)) reference = &
                merge(abs(check%references(k)), check%references(k), check%absolute_values)
        end do
        tolerance = check%tolerance
        if (is_absolute(check%criterion) .and. ieee_is_finite(check%magnitude)) &
            tolerance = tolerance * abs(check%magnitude)
        ok = test_resu_passes(reference, value, tolerance, check%criterion)
        verdict = merge(CHECK_OK, CHECK_NOOK, ok)
        if (is_absolute(check%criterion)) then
            error_text = absolute_error_text(reference, value)
            tolerance_text = finite_short(tolerance)
        else
            error_text = relative_error_text(reference, value) // '%'
            tolerance_text = percent_text(tolerance) // '%'
        end if
        if (check%integers) then
            ref_text = integer_text(reference)
            val_text = integer_text(value)
        else
            ref_text = real_e13(reference)
            val_text = real_e13(value)
        end if
        line = merge(' OK   ', 'NOOK  ', ok) // field(KIND_WIDTH, check%kind) // &
            field(LEGEND_WIDTH, legend) // field(VALUE_WIDTH, ref_text) // &
            field(VALUE_WIDTH, val_text) // field(ERROR_WIDTH, error_text) // tolerance_text
    end subroutine test_check_line

    !> An integral value as an integer (within the default integer range), else in E format.
    pure function integer_text(value) result(text)
        real(dp), intent(in) :: value
        character(len=:), allocatable :: text
        character(len=24) :: buf
        if (ieee_is_finite(value) .and. abs(value) < 2.0_dp**31 .and. &
            .not. abs(value - aint(value)) > 0.0_dp) then
            write (buf, '(i0)') nint(value)
            text = trim(buf)
        else
            text = real_e13(value)
        end if
    end function integer_text

    !> A whole block: identification lines, header, one line per check.
    !>  titles, values : in, the identification columns (test_resu_id_columns)
    !>  checks         : in, the checks, NON_REGRESSION first
    !>  computed       : in, the tested value
    !>  lines          : out, 3 + size(checks) lines
    !>  n_ok, n_nook   : inout, incremented by the verdicts (skipped checks count in neither)
    pure subroutine test_check_block(titles, values, checks, computed, lines, n_ok, n_nook)
        type(string_t), intent(in) :: titles(:), values(:)
        type(test_check_t), intent(in) :: checks(:)
        real(dp), intent(in) :: computed
        type(string_t), allocatable, intent(out) :: lines(:)
        integer, intent(inout) :: n_ok, n_nook
        type(string_t) :: id(2)
        integer :: k, verdict
        allocate (lines(3 + size(checks)))
        call test_resu_id_columns(titles, values, id)
        lines(1:2) = id
        lines(3)%s = test_resu_header_line()
        do k = 1, size(checks)
            call test_check_line(checks(k), computed, lines(3 + k)%s, verdict)
            if (verdict == CHECK_OK) n_ok = n_ok + 1
            if (verdict == CHECK_NOOK) n_nook = n_nook + 1
        end do
    end subroutine test_check_block

    !> The header of the check table:
    !> `      REFERENCE        LEGENDE          VALE_REFE ... ERREUR          TOLE`.
    pure function test_resu_header_line() result(line)
        character(len=:), allocatable :: line
        line = repeat(' ', PREFIX_WIDTH) // field(KIND_WIDTH, 'REFERENCE') // &
               field(LEGEND_WIDTH, 'LEGENDE') // field(VALUE_WIDTH, 'VALE_REFE') // &
               field(VALUE_WIDTH, 'VALE_CALC') // field(ERROR_WIDTH, 'ERREUR') // 'TOLE'
    end function test_resu_header_line

    !> True for the criteria TEST_RESU knows: 'RELATIF' and 'ABSOLU' (any case).
    pure logical function is_test_resu_criterion(criterion)
        character(len=*), intent(in) :: criterion
        is_test_resu_criterion = to_upper(trim(criterion)) == 'RELATIF' .or. &
                                 to_upper(trim(criterion)) == 'ABSOLU'
    end function is_test_resu_criterion

    !> Verdict of one check (listings.md):
    !>   RELATIF: OK iff |ref - val| <= tol*|ref|   (ref = 0: OK iff val = 0 exactly)
    !>   ABSOLU : OK iff |ref - val| <= tol
    !> Non-finite values never pass. Never raises a floating-point exception.
    !>  reference, computed, tolerance : in, the values (tolerance >= 0, a fraction not %)
    !>  criterion : in, 'RELATIF' or 'ABSOLU' (anything but 'ABSOLU' is taken as RELATIF;
    !>              callers validate with is_test_resu_criterion)
    pure logical function test_resu_passes(reference, computed, tolerance, criterion)
        real(dp), intent(in) :: reference, computed, tolerance
        character(len=*), intent(in) :: criterion
        real(dp) :: scale, difference
        test_resu_passes = .false.
        if (.not. (ieee_is_finite(reference) .and. ieee_is_finite(computed) .and. &
                   ieee_is_finite(tolerance))) return
        if (tolerance < 0.0_dp) return
        scale = max(abs(reference), abs(computed))
        if (scale > huge(1.0_dp) / 4.0_dp) then
            ! |ref - val| could overflow: compare halves, exact (division by 2 is exact).
            difference = abs(reference / 2.0_dp - computed / 2.0_dp)
            if (is_absolute(criterion)) then
                test_resu_passes = difference <= tolerance / 2.0_dp
            else
                if (tolerance > 1.0_dp) then
                    test_resu_passes = difference / tolerance <= abs(reference) / 2.0_dp
                else
                    test_resu_passes = difference <= tolerance * (abs(reference) / 2.0_dp)
                end if
            end if
            return
        end if
        difference = abs(reference - computed)
        if (is_absolute(criterion)) then
            test_resu_passes = difference <= tolerance
        else if (abs(reference) <= 0.0_dp) then
            test_resu_passes = abs(computed) <= 0.0_dp
        else if (tolerance > 1.0_dp) then
            ! tol*|ref| may overflow (TOLE_MACHINE = 1e308): divide the difference instead,
            ! which cannot (tol > 1)
            test_resu_passes = difference / tolerance <= abs(reference)
        else
            test_resu_passes = difference <= tolerance * abs(reference)
        end if
    end function test_resu_passes

    !> One check line, e.g.
    !> ` OK   NON_REGRESSION   XXXX   -3.5...E-03   -3.5...E-03   3.31E-09%   1.00E-04%`.
    !>  reference_kind : in, NON_REGRESSION, ANALYTIQUE, AUTRE_ASTER or SOURCE_EXTERNE
    !>  legend         : in, LEGENDE; blank gives XXXX
    !>  reference, computed, tolerance, criterion : in, as in test_resu_passes
    !>  line           : out, the line
    !>  ok             : out, the verdict (true = OK)
    pure subroutine test_resu_check_line(reference_kind, legend, reference, computed, &
                                         tolerance, criterion, line, ok)
        character(len=*), intent(in) :: reference_kind, legend, criterion
        real(dp), intent(in) :: reference, computed, tolerance
        character(len=:), allocatable, intent(out) :: line
        logical, intent(out) :: ok
        character(len=:), allocatable :: error_text, tolerance_text, legend_text
        ok = test_resu_passes(reference, computed, tolerance, criterion)
        legend_text = trim(legend)
        if (len(legend_text) == 0) legend_text = TEST_RESU_NO_LEGEND
        if (is_absolute(criterion)) then
            error_text = absolute_error_text(reference, computed)
            tolerance_text = finite_short(tolerance)
        else
            error_text = relative_error_text(reference, computed) // '%'
            tolerance_text = percent_text(tolerance) // '%'
        end if
        if (ok) then
            line = ' OK   '
        else
            line = 'NOOK  '
        end if
        line = line // field(KIND_WIDTH, trim(reference_kind)) // &
               field(LEGEND_WIDTH, legend_text) // field(VALUE_WIDTH, real_e13(reference)) // &
               field(VALUE_WIDTH, real_e13(computed)) // field(ERROR_WIDTH, error_text) // &
               tolerance_text
    end subroutine test_resu_check_line

    !> A whole TEST_RESU block for one tested value: identification lines, header, the
    !> NON_REGRESSION line against VALE_CALC and, when `reference_kind` is present, a second
    !> line against VALE_REFE (listings.md).
    !>  result_name, field_name, component, location_kind, location_name : in, as in
    !>                   test_resu_id_lines
    !>  vale_calc      : in, the non-regression value of the deck
    !>  computed       : in, the value parasol computed
    !>  tole_machine   : in, tolerance of the NON_REGRESSION check (fraction, not %)
    !>  criterion      : in, 'RELATIF' or 'ABSOLU' (both checks)
    !>  lines          : out, the 4 or 5 lines
    !>  n_ok, n_nook   : inout, incremented by the verdicts of the block
    !>  nume_ordre, inst : in, optional, as in test_resu_id_lines
    !>  reference_kind : in, optional, ANALYTIQUE, AUTRE_ASTER or SOURCE_EXTERNE
    !>  vale_refe, precision, legend : in, optional, the reference check (precision defaults to
    !>                   TEST_RESU_DEFAULT_PRECISION; vale_refe is needed with reference_kind)
    pure subroutine test_resu_block_lines(result_name, field_name, component, location_kind, &
                                          location_name, vale_calc, computed, tole_machine, &
                                          criterion, lines, n_ok, n_nook, nume_ordre, inst, &
                                          reference_kind, vale_refe, precision, legend, point)
        character(len=*), intent(in) :: result_name, field_name, component, location_kind, &
                                        location_name, criterion
        real(dp), intent(in) :: vale_calc, computed, tole_machine
        type(string_t), allocatable, intent(out) :: lines(:)
        integer, intent(inout) :: n_ok, n_nook
        integer, intent(in), optional :: nume_ordre, point
        real(dp), intent(in), optional :: inst, vale_refe, precision
        character(len=*), intent(in), optional :: reference_kind, legend
        type(string_t) :: id_lines(2)
        logical :: with_reference, ok
        real(dp) :: tolerance
        with_reference = present(reference_kind) .and. present(vale_refe)
        allocate (lines(merge(5, 4, with_reference)))
        call test_resu_id_lines(result_name, field_name, component, location_kind, &
                                location_name, id_lines, nume_ordre, inst, point)
        lines(1:2) = id_lines
        lines(3)%s = test_resu_header_line()
        call test_resu_check_line('NON_REGRESSION', '', vale_calc, computed, tole_machine, &
                                  criterion, lines(4)%s, ok)
        if (ok) n_ok = n_ok + 1
        if (.not. ok) n_nook = n_nook + 1
        if (.not. with_reference) return
        tolerance = TEST_RESU_DEFAULT_PRECISION
        if (present(precision)) tolerance = precision
        if (present(legend)) then
            call test_resu_check_line(reference_kind, legend, vale_refe, computed, tolerance, &
                                      criterion, lines(5)%s, ok)
        else
            call test_resu_check_line(reference_kind, '', vale_refe, computed, tolerance, &
                                      criterion, lines(5)%s, ok)
        end if
        if (ok) n_ok = n_ok + 1
        if (.not. ok) n_nook = n_nook + 1
    end subroutine test_resu_block_lines

    !> The one-line verdict ending the .mess: `TEST_RESU: 3 OK, 1 NOOK` .
    pure function test_resu_summary_line(n_ok, n_nook) result(line)
        integer, intent(in) :: n_ok, n_nook
        character(len=:), allocatable :: line
        character(len=12) :: a, b
        write (a, '(i0)') n_ok
        write (b, '(i0)') n_nook
        line = 'TEST_RESU: ' // trim(a) // ' OK, ' // trim(b) // ' NOOK'
    end function test_resu_summary_line

    !> |ref - val| with 3 digits, overflow-safe; non-finite inputs give +Inf or NaN.
    pure function absolute_error_text(reference, computed) result(text)
        real(dp), intent(in) :: reference, computed
        character(len=:), allocatable :: text
        if (.not. (ieee_is_finite(reference) .and. ieee_is_finite(computed))) then
            text = 'NaN'
        else if (max(abs(reference), abs(computed)) > huge(1.0_dp) / 4.0_dp) then
            text = finite_short(2.0_dp * min(abs(reference / 2.0_dp - computed / 2.0_dp), &
                                             huge(1.0_dp) / 2.0_dp))
        else
            text = real_short(abs(reference - computed))
        end if
    end function absolute_error_text

    !> 100*|ref - val|/|ref| with 3 digits, or +Inf when it is not a finite number (ref = 0
    !> with val /= 0, or too large), 0.00E+00 when ref = val = 0; never divides by zero.
    pure function relative_error_text(reference, computed) result(text)
        real(dp), intent(in) :: reference, computed
        character(len=:), allocatable :: text
        real(dp) :: difference, magnitude, ratio
        if (.not. (ieee_is_finite(reference) .and. ieee_is_finite(computed))) then
            text = 'NaN'
            return
        end if
        magnitude = abs(reference)
        difference = abs(reference / 2.0_dp - computed / 2.0_dp)    ! half, overflow-safe
        text = INFINITE_ERROR
        if (difference <= 0.0_dp) then
            text = real_short(0.0_dp)
            return
        else if (magnitude <= 0.0_dp) then
            return
        else if (magnitude < 1.0_dp) then
            if (difference > magnitude * (huge(1.0_dp) / 400.0_dp)) return
        end if
        ratio = difference / magnitude
        if (ratio <= huge(1.0_dp) / 400.0_dp) text = real_short(200.0_dp * ratio)
    end function relative_error_text

    !> 100*tolerance with 3 digits, overflow-safe.
    pure function percent_text(tolerance) result(text)
        real(dp), intent(in) :: tolerance
        character(len=:), allocatable :: text
        if (.not. ieee_is_finite(tolerance) .or. abs(tolerance) > huge(1.0_dp) / 100.0_dp) then
            text = INFINITE_ERROR
        else
            text = real_short(100.0_dp * tolerance)
        end if
    end function percent_text

    !> real_short of a value, +Inf when not finite.
    pure function finite_short(value) result(text)
        real(dp), intent(in) :: value
        character(len=:), allocatable :: text
        if (ieee_is_finite(value)) then
            text = real_short(value)
        else
            text = INFINITE_ERROR
        end if
    end function finite_short

    pure logical function is_absolute(criterion)
        character(len=*), intent(in) :: criterion
        is_absolute = to_upper(trim(criterion)) == 'ABSOLU'
    end function is_absolute

    !> `text` left-aligned in `width` columns, or followed by one blank when longer.
    pure function field(width, text) result(out)
        integer, intent(in) :: width
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: out
        out = text // repeat(' ', max(1, width - len(text)))
    end function field

end module test_resu_format
