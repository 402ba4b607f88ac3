!> Reductions of a table column to one value: TEST_TABLE's TYPE_TEST (SOMM, SOMM_ABS, MAX,
!> MIN) and CALC_TABLE's TYPE_CALCUL (SOMM, SOMM_ABS, MAXI, MINI, MAXI_ABS, MINI_ABS, MOY).
!> Cells may hold any finite double, so sums are formed so that they cannot overflow: when
!> a plain sum could pass the largest double, the terms are summed scaled by 2**-64 (exact)
!> and a total beyond double precision is an error, never an Inf; integer sums that would
!> not fit in 64 bits are errors too.
module table_reduce
    use kinds, only: dp, i8
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use number_limits, only: MAX_BINARY_EXPONENT
    implicit none
    private

    !> The scaling of a guarded sum (a power of two: exact).
    integer, parameter :: SUM_SCALING = 64
    !> A plain sum of at most this many terms, each below 2**MAX_BINARY_EXPONENT, is finite.
    integer, parameter :: PLAIN_SUM_TERMS = 2**20

    public :: reduce_reals, reduce_ints, guarded_sum

contains

    !> One reduction of `x` (at least one value).
    !>  operation : SOMM, SOMM_ABS, MAX/MAXI, MIN/MINI, MAXI_ABS, MINI_ABS, MOY
    !>  st : STATUS_MODEL_ERROR when a sum is beyond double precision
    subroutine reduce_reals(x, operation, value, st)
        real(dp), intent(in) :: x(:)
        character(len=*), intent(in) :: operation
        real(dp), intent(out) :: value
        type(status_t), intent(inout) :: st
        value = 0.0_dp
        if (size(x) == 0) return
        select case (operation)
        case ('SOMM')
            call guarded_sum(x, value, st)
        case ('SOMM_ABS')
            call guarded_sum(abs(x), value, st)
        case ('MAX', 'MAXI')
            value = maxval(x)
        case ('MIN', 'MINI')
            value = minval(x)
        case ('MAXI_ABS')
            value = maxval(abs(x))
        case ('MINI_ABS')
            value = minval(abs(x))
        case ('MOY')
            ! the mean of the scaled terms, then scaled back: never overflows
            value = scale(sum(scale(x, -SUM_SCALING)) / real(size(x), dp), SUM_SCALING)
            if (maxval(abs(x)) < 2.0_dp**MAX_BINARY_EXPONENT .and. &
                size(x) <= PLAIN_SUM_TERMS) value = sum(x) / real(size(x), dp)
        end select
    end subroutine reduce_reals

    !> One reduction of integers (MOY is not an integer: reduce_reals takes it).
    !>  st : STATUS_MODEL_ERROR when a sum does not fit in 64 bits
    subroutine reduce_ints(n, operation, value, st)
        integer(i8), intent(in) :: n(:)
        character(len=*), intent(in) :: operation
        integer(i8), intent(out) :: value
        type(status_t), intent(inout) :: st
        real(dp) :: estimate
        value = 0
        if (size(n) == 0) return
        select case (operation)
        case ('SOMM', 'SOMM_ABS')
            estimate = sum(abs(real(n, dp)))
            if (estimate >= 0.5_dp * real(huge(value), dp) .or. any(n == -huge(value) - 1)) then
                call set_error(st, STATUS_MODEL_ERROR, 'the sum of the integers does not ' // &
                    'fit in 64 bits')
                return
            end if
            if (operation == 'SOMM') then
                value = sum(n)
            else
                value = sum(abs(n))
            end if
        case ('MAX', 'MAXI')
            value = maxval(n)
        case ('MIN', 'MINI')
            value = minval(n)
        case ('MAXI_ABS', 'MINI_ABS')
            if (any(n == -huge(value) - 1)) then
                call set_error(st, STATUS_MODEL_ERROR, 'the absolute value of ' // &
                    '-9223372036854775808 does not fit in 64 bits')
                return
            end if
            if (operation == 'MAXI_ABS') value = maxval(abs(n))
            if (operation == 'MINI_ABS') value = minval(abs(n))
        end select
    end subroutine reduce_ints

    !> sum(x), formed without overflow.
    !>  st : STATUS_MODEL_ERROR when the sum itself is beyond double precision
    subroutine guarded_sum(x, total, st)
        real(dp), intent(in) :: x(:)
        real(dp), intent(out) :: total
        type(status_t), intent(inout) :: st
        real(dp) :: scaled
        total = 0.0_dp
        if (size(x) == 0) return
        if (maxval(abs(x)) < 2.0_dp**MAX_BINARY_EXPONENT .and. size(x) <= PLAIN_SUM_TERMS) then
            total = sum(x)
            return
        end if
        scaled = sum(scale(x, -SUM_SCALING))
        if (abs(scaled) > 0.0_dp) then
            if (exponent(scaled) + SUM_SCALING > maxexponent(scaled)) then
                call set_error(st, STATUS_MODEL_ERROR, 'the sum is beyond double ' // &
                    'precision (about 1.8E+308)')
                return
            end if
        end if
        total = scale(scaled, SUM_SCALING)
    end subroutine guarded_sum

end module table_reduce
