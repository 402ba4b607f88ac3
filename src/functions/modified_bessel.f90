!> Modified Bessel functions of the first kind I0 and I1, exponentially scaled
!> (e^-x I_nu(x), x >= 0), and the scaled derivative e^-x I1'(x) = e^-x (I0(x) - I1(x)/x)
!> (Abramowitz & Stegun 9.6.10 power series, 9.7.1 asymptotic expansion, 9.6.27 derivative).
!> Scaled, they stay finite for any x: DEFI_PRES_EC8's ratios I1(a)/I1'(b) are formed as
!> e^-a I1(a) / (e^-b I1'(b)) * e^(a-b) without overflowing for large a, b.
module modified_bessel
    use kinds, only: dp
    implicit none
    private

    !> Below it the power series (positive terms, no cancellation, largest term about e^x:
    !> finite), above it the asymptotic expansion, whose smallest term (near k = 2x) is about
    !> e^-2x, far below double precision at x = 30.
    real(dp), parameter :: SERIES_LIMIT = 30.0_dp
    !> Most terms either expansion takes (the power series needs about x + 40 at x = 30).
    integer, parameter :: MAX_TERMS = 200

    public :: scaled_i0, scaled_i1, scaled_i1_derivative

contains

    !> e^-x I0(x), x >= 0.
    elemental real(dp) function scaled_i0(x)
        real(dp), intent(in) :: x
        scaled_i0 = scaled_i(0, x)
    end function scaled_i0

    !> e^-x I1(x), x >= 0.
    elemental real(dp) function scaled_i1(x)
        real(dp), intent(in) :: x
        scaled_i1 = scaled_i(1, x)
    end function scaled_i1

    !> e^-x I1'(x) = e^-x (I0(x) - I1(x) / x), x > 0 (A&S 9.6.27); 1/2 at x = 0.
    elemental real(dp) function scaled_i1_derivative(x)
        real(dp), intent(in) :: x
        if (x > 0.0_dp) then
            scaled_i1_derivative = scaled_i(0, x) - scaled_i(1, x) / x
        else
            scaled_i1_derivative = 0.5_dp
        end if
    end function scaled_i1_derivative

    !> e^-x I_nu(x) for nu = 0 or 1 and x >= 0.
    elemental real(dp) function scaled_i(nu, x)
        integer, intent(in) :: nu
        real(dp), intent(in) :: x
        if (x <= SERIES_LIMIT) then
            scaled_i = power_series(nu, x) * exp(-x)
        else
            scaled_i = asymptotic(nu, x)
        end if
    end function scaled_i

    !> I_nu(x) = sum_k (x/2)^(2k+nu) / (k! (k+nu)!)  (A&S 9.6.10), 0 <= x <= SERIES_LIMIT.
    elemental real(dp) function power_series(nu, x)
        integer, intent(in) :: nu
        real(dp), intent(in) :: x
        real(dp) :: term, q
        integer :: k
        term = 1.0_dp
        if (nu == 1) term = 0.5_dp * x
        power_series = term
        q = 0.25_dp * x * x
        do k = 1, MAX_TERMS
            term = term * q / (real(k, dp) * real(k + nu, dp))
            power_series = power_series + term
            if (term <= epsilon(1.0_dp) * 0.25_dp * power_series) exit
        end do
    end function power_series

    !> e^-x I_nu(x) ~ (2 pi x)^-1/2 sum_k (-1)^k a_k(nu) / x^k, a_k = prod_{j<=k}
    !> (4 nu^2 - (2j-1)^2) / (8 j)  (A&S 9.7.1), x > SERIES_LIMIT; summed until the terms
    !> stop decreasing or fall below the precision.
    elemental real(dp) function asymptotic(nu, x)
        integer, intent(in) :: nu
        real(dp), intent(in) :: x
        real(dp), parameter :: PI = acos(-1.0_dp)
        real(dp) :: term, next, mu, total
        integer :: k
        mu = 4.0_dp * real(nu * nu, dp)
        term = 1.0_dp
        total = 1.0_dp
        do k = 1, MAX_TERMS
            next = -term * (mu - real((2 * k - 1)**2, dp)) / (8.0_dp * real(k, dp) * x)
            if (abs(next) >= abs(term)) exit
            term = next
            total = total + term
            if (abs(term) <= epsilon(1.0_dp) * 0.25_dp * abs(total)) exit
        end do
        asymptotic = total / sqrt(2.0_dp * PI * x)
    end function asymptotic

end module modified_bessel
