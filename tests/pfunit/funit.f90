!> parasol's own assertion module for the pFUnit subset (used when pFUnit 4 is not found).
!>
!> Each `funit_assert_*` routine checks one condition and, on failure, prints
!> `file:line: FAILED suite%test: what was expected and what was found` and marks the
!> current test failed. Test code never calls these directly: the preprocessor turns the
!> `@assert...` annotations of a `.pf` suite into calls. Semantics follow pFUnit 4:
!> assertEqual on reals passes when |expected - actual| <= tolerance (0 if absent);
!> assertRelativelyEqual when |expected - actual| <= tolerance * |expected|;
!> assertLessThan(a, b) when a < b, and so on.
!> This is test infrastructure, so its run counters are module variables.
module funit
    use, intrinsic :: iso_fortran_env, only: real64, int32, int64, output_unit
    implicit none
    private
    integer, parameter :: dp = real64

    integer :: n_tests = 0, n_failed_tests = 0
    logical :: current_failed = .false.
    character(len=:), allocatable :: current_name

    interface funit_assert_equal
        module procedure eq_i4, eq_i8, eq_i4_i4v, eq_i4v_i4v, eq_i8v_i8v, eq_r, eq_r_rv, &
            eq_rv_rv, eq_rm_rm, eq_c, eq_l
    end interface funit_assert_equal
    interface funit_assert_relatively_equal
        module procedure rel_r, rel_rv_rv
    end interface funit_assert_relatively_equal
    interface funit_assert_less_than
        module procedure lt_i, lt_r
    end interface funit_assert_less_than
    interface funit_assert_less_than_or_equal
        module procedure le_i, le_r
    end interface funit_assert_less_than_or_equal
    interface funit_assert_greater_than
        module procedure gt_i, gt_r
    end interface funit_assert_greater_than
    interface funit_assert_greater_than_or_equal
        module procedure ge_i, ge_r
    end interface funit_assert_greater_than_or_equal

    public :: funit_assert_equal, funit_assert_relatively_equal, funit_assert_true, &
        funit_assert_false, funit_assert_less_than, funit_assert_less_than_or_equal, &
        funit_assert_greater_than, funit_assert_greater_than_or_equal, funit_assert_all, &
        funit_assert_any, funit_failed, funit_start_test, funit_end_test, funit_finish

contains

    ! ---- run bookkeeping -------------------------------------------------------------------
    subroutine funit_start_test(suite, test)
        character(len=*), intent(in) :: suite, test
        current_name = suite // '%' // test
        current_failed = .false.
        n_tests = n_tests + 1
    end subroutine funit_start_test

    subroutine funit_end_test()
        if (current_failed) then
            n_failed_tests = n_failed_tests + 1
            write (output_unit, '(a)') 'FAIL  ' // current_name
        else
            write (output_unit, '(a)') 'ok    ' // current_name
        end if
        flush (output_unit)
    end subroutine funit_end_test

    !> Prints the suite summary and exits with status 1 when any test failed.
    subroutine funit_finish(suite)
        character(len=*), intent(in) :: suite
        write (output_unit, '(a, i0, a, i0, a)') suite // ': ', n_tests - n_failed_tests, &
            ' passed, ', n_failed_tests, ' failed'
        flush (output_unit)
        if (n_failed_tests > 0) stop 1, quiet=.true.
    end subroutine funit_finish

    !> True once an assertion of the current test has failed (the generated code returns).
    logical function funit_failed()
        funit_failed = current_failed
    end function funit_failed

    subroutine fail(what, message, file, line)
        character(len=*), intent(in) :: what
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        character(len=16) :: buf
        current_failed = .true.
        write (buf, '(i0)') line
        if (present(message)) then
            write (output_unit, '(a)') file // ':' // trim(buf) // ': FAILED ' // &
                current_name // ': ' // message // ': ' // what
        else
            write (output_unit, '(a)') file // ':' // trim(buf) // ': FAILED ' // &
                current_name // ': ' // what
        end if
    end subroutine fail

    function r2s(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        character(len=40) :: buf
        write (buf, '(es24.16e3)') x
        s = trim(adjustl(buf))
    end function r2s

    function i2s(i) result(s)
        integer(int64), intent(in) :: i
        character(len=:), allocatable :: s
        character(len=24) :: buf
        write (buf, '(i0)') i
        s = trim(buf)
    end function i2s

    ! ---- assertEqual -----------------------------------------------------------------------
    subroutine eq_i4(expected, actual, message, file, line)
        integer(int32), intent(in) :: expected, actual
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        if (expected /= actual) call fail('expected ' // i2s(int(expected, int64)) // &
            ' but found ' // i2s(int(actual, int64)), message, file, line)
    end subroutine eq_i4

    subroutine eq_i8(expected, actual, message, file, line)
        integer(int64), intent(in) :: expected, actual
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        if (expected /= actual) call fail('expected ' // i2s(expected) // ' but found ' // &
            i2s(actual), message, file, line)
    end subroutine eq_i8

    subroutine eq_i4_i4v(expected, actual, message, file, line)
        integer(int32), intent(in) :: expected, actual(:)
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        integer :: i
        do i = 1, size(actual)
            if (actual(i) /= expected) then
                call fail('expected ' // i2s(int(expected, int64)) // ' but found ' // &
                    i2s(int(actual(i), int64)) // ' at index ' // i2s(int(i, int64)), &
                    message, file, line)
                return
            end if
        end do
    end subroutine eq_i4_i4v

    subroutine eq_i4v_i4v(expected, actual, message, file, line)
        integer(int32), intent(in) :: expected(:), actual(:)
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        integer :: i
        if (size(expected) /= size(actual)) then
            call fail('arrays differ in size: expected ' // i2s(int(size(expected), int64)) &
                // ' but found ' // i2s(int(size(actual), int64)), message, file, line)
            return
        end if
        do i = 1, size(actual)
            if (actual(i) /= expected(i)) then
                call fail('expected ' // i2s(int(expected(i), int64)) // ' but found ' // &
                    i2s(int(actual(i), int64)) // ' at index ' // i2s(int(i, int64)), &
                    message, file, line)
                return
            end if
        end do
    end subroutine eq_i4v_i4v

    subroutine eq_i8v_i8v(expected, actual, message, file, line)
        integer(int64), intent(in) :: expected(:), actual(:)
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        integer :: i
        if (size(expected) /= size(actual)) then
            call fail('arrays differ in size', message, file, line)
            return
        end if
        do i = 1, size(actual)
            if (actual(i) /= expected(i)) then
                call fail('expected ' // i2s(expected(i)) // ' but found ' // &
                    i2s(actual(i)) // ' at index ' // i2s(int(i, int64)), message, file, line)
                return
            end if
        end do
    end subroutine eq_i8v_i8v

    subroutine eq_r(expected, actual, tolerance, message, file, line)
        real(dp), intent(in) :: expected, actual
        real(dp), intent(in), optional :: tolerance
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        real(dp) :: tol
        tol = 0.0_dp
        if (present(tolerance)) tol = tolerance
        if (.not. (abs(expected - actual) <= tol)) call fail('expected ' // r2s(expected) // &
            ' but found ' // r2s(actual) // ' (tolerance ' // r2s(tol) // ')', &
            message, file, line)
    end subroutine eq_r

    subroutine eq_r_rv(expected, actual, tolerance, message, file, line)
        real(dp), intent(in) :: expected, actual(:)
        real(dp), intent(in), optional :: tolerance
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        real(dp) :: tol
        integer :: i
        tol = 0.0_dp
        if (present(tolerance)) tol = tolerance
        do i = 1, size(actual)
            if (.not. (abs(expected - actual(i)) <= tol)) then
                call fail('expected ' // r2s(expected) // ' but found ' // r2s(actual(i)) // &
                    ' at index ' // i2s(int(i, int64)) // ' (tolerance ' // r2s(tol) // ')', &
                    message, file, line)
                return
            end if
        end do
    end subroutine eq_r_rv

    subroutine eq_rv_rv(expected, actual, tolerance, message, file, line)
        real(dp), intent(in) :: expected(:), actual(:)
        real(dp), intent(in), optional :: tolerance
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        real(dp) :: tol
        integer :: i
        tol = 0.0_dp
        if (present(tolerance)) tol = tolerance
        if (size(expected) /= size(actual)) then
            call fail('arrays differ in size: expected ' // i2s(int(size(expected), int64)) &
                // ' but found ' // i2s(int(size(actual), int64)), message, file, line)
            return
        end if
        do i = 1, size(actual)
            if (.not. (abs(expected(i) - actual(i)) <= tol)) then
                call fail('expected ' // r2s(expected(i)) // ' but found ' // &
                    r2s(actual(i)) // ' at index ' // i2s(int(i, int64)) // &
                    ' (tolerance ' // r2s(tol) // ')', message, file, line)
                return
            end if
        end do
    end subroutine eq_rv_rv

    subroutine eq_rm_rm(expected, actual, tolerance, message, file, line)
        real(dp), intent(in) :: expected(:, :), actual(:, :)
        real(dp), intent(in), optional :: tolerance
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        real(dp) :: tol
        integer :: i, j
        tol = 0.0_dp
        if (present(tolerance)) tol = tolerance
        if (any(shape(expected) /= shape(actual))) then
            call fail('arrays differ in shape', message, file, line)
            return
        end if
        do j = 1, size(actual, 2)
            do i = 1, size(actual, 1)
                if (.not. (abs(expected(i, j) - actual(i, j)) <= tol)) then
                    call fail('expected ' // r2s(expected(i, j)) // ' but found ' // &
                        r2s(actual(i, j)) // ' at (' // i2s(int(i, int64)) // ',' // &
                        i2s(int(j, int64)) // ') (tolerance ' // r2s(tol) // ')', &
                        message, file, line)
                    return
                end if
            end do
        end do
    end subroutine eq_rm_rm

    subroutine eq_c(expected, actual, message, file, line)
        character(len=*), intent(in) :: expected, actual
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        if (expected /= actual) call fail('expected "' // expected // '" but found "' // &
            actual // '"', message, file, line)
    end subroutine eq_c

    subroutine eq_l(expected, actual, message, file, line)
        logical, intent(in) :: expected, actual
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        if (expected .neqv. actual) call fail('logical values differ', message, file, line)
    end subroutine eq_l

    ! ---- assertRelativelyEqual -------------------------------------------------------------
    subroutine rel_r(expected, actual, tolerance, message, file, line)
        real(dp), intent(in) :: expected, actual, tolerance
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        if (.not. (abs(expected - actual) <= tolerance * abs(expected))) call fail( &
            'expected ' // r2s(expected) // ' but found ' // r2s(actual) // &
            ' (relative tolerance ' // r2s(tolerance) // ')', message, file, line)
    end subroutine rel_r

    subroutine rel_rv_rv(expected, actual, tolerance, message, file, line)
        real(dp), intent(in) :: expected(:), actual(:), tolerance
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        integer :: i
        if (size(expected) /= size(actual)) then
            call fail('arrays differ in size', message, file, line)
            return
        end if
        do i = 1, size(actual)
            if (.not. (abs(expected(i) - actual(i)) <= tolerance * abs(expected(i)))) then
                call fail('expected ' // r2s(expected(i)) // ' but found ' // &
                    r2s(actual(i)) // ' at index ' // i2s(int(i, int64)) // &
                    ' (relative tolerance ' // r2s(tolerance) // ')', message, file, line)
                return
            end if
        end do
    end subroutine rel_rv_rv

    ! ---- assertTrue / assertFalse / assertAll / assertAny ----------------------------------
    subroutine funit_assert_true(condition, message, file, line)
        logical, intent(in) :: condition
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        if (.not. condition) call fail('expected .true.', message, file, line)
    end subroutine funit_assert_true

    subroutine funit_assert_false(condition, message, file, line)
        logical, intent(in) :: condition
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        if (condition) call fail('expected .false.', message, file, line)
    end subroutine funit_assert_false

    subroutine funit_assert_all(conditions, message, file, line)
        logical, intent(in) :: conditions(:)
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        if (.not. all(conditions)) call fail('expected all .true., ' // &
            i2s(int(count(.not. conditions), int64)) // ' are .false.', message, file, line)
    end subroutine funit_assert_all

    subroutine funit_assert_any(conditions, message, file, line)
        logical, intent(in) :: conditions(:)
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        if (.not. any(conditions)) call fail('expected at least one .true.', message, file, line)
    end subroutine funit_assert_any

    ! ---- ordering --------------------------------------------------------------------------
    subroutine lt_i(a, b, message, file, line)
        integer(int32), intent(in) :: a, b
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        if (.not. (a < b)) call fail('expected ' // i2s(int(a, int64)) // ' < ' // &
            i2s(int(b, int64)), message, file, line)
    end subroutine lt_i

    subroutine lt_r(a, b, message, file, line)
        real(dp), intent(in) :: a, b
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        if (.not. (a < b)) call fail('expected ' // r2s(a) // ' < ' // r2s(b), message, file, line)
    end subroutine lt_r

    subroutine le_i(a, b, message, file, line)
        integer(int32), intent(in) :: a, b
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        if (.not. (a <= b)) call fail('expected ' // i2s(int(a, int64)) // ' <= ' // &
            i2s(int(b, int64)), message, file, line)
    end subroutine le_i

    subroutine le_r(a, b, message, file, line)
        real(dp), intent(in) :: a, b
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        if (.not. (a <= b)) call fail('expected ' // r2s(a) // ' <= ' // r2s(b), &
            message, file, line)
    end subroutine le_r

    subroutine gt_i(a, b, message, file, line)
        integer(int32), intent(in) :: a, b
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        if (.not. (a > b)) call fail('expected ' // i2s(int(a, int64)) // ' > ' // &
            i2s(int(b, int64)), message, file, line)
    end subroutine gt_i

    subroutine gt_r(a, b, message, file, line)
        real(dp), intent(in) :: a, b
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        if (.not. (a > b)) call fail('expected ' // r2s(a) // ' > ' // r2s(b), message, file, line)
    end subroutine gt_r

    subroutine ge_i(a, b, message, file, line)
        integer(int32), intent(in) :: a, b
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        if (.not. (a >= b)) call fail('expected ' // i2s(int(a, int64)) // ' >= ' // &
            i2s(int(b, int64)), message, file, line)
    end subroutine ge_i

    subroutine ge_r(a, b, message, file, line)
        real(dp), intent(in) :: a, b
        character(len=*), intent(in), optional :: message
        character(len=*), intent(in) :: file
        integer, intent(in) :: line
        if (.not. (a >= b)) call fail('expected ' // r2s(a) // ' >= ' // r2s(b), &
            message, file, line)
    end subroutine ge_r

end module funit
