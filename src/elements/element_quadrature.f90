!> Quadrature rules used by the element kernels (points in the reference element, weights).
!>
!> Quadrilateral rules live on [-1,1]^2 (weights sum to 4); triangle rules use area
!> coordinates (xi, eta) with L3 = 1 - xi - eta (weights sum to 1/2, the reference area);
!> line rules live on [-1,1] (weights sum to 2).
module element_quadrature
    use kinds, only: dp, i4
    implicit none
    private

    public :: gauss_line, gauss_quad, hammer_tria3

contains

    !> Gauss-Legendre rule on [-1,1] with n = 2 or 3 points (exact to degree 2n-1).
    !>  n  : in, number of points (2 or 3; any other value gives the 2-point rule)
    !>  xi : out, abscissae; w : out, weights
    pure subroutine gauss_line(n, xi, w)
        integer(i4), intent(in) :: n
        real(dp), intent(out) :: xi(:), w(:)
        if (n == 3) then
            xi(1:3) = [-sqrt(0.6_dp), 0.0_dp, sqrt(0.6_dp)]
            w(1:3) = [5.0_dp, 8.0_dp, 5.0_dp] / 9.0_dp
        else
            xi(1:2) = [-1.0_dp, 1.0_dp] / sqrt(3.0_dp)
            w(1:2) = [1.0_dp, 1.0_dp]
        end if
    end subroutine gauss_line

    !> Tensor-product Gauss rule n x n on [-1,1]^2 (exact to degree 2n-1 per direction).
    !>  n  : in, points per direction (2 or 3)
    !>  xi : out, xi(1:2, n*n) reference coordinates; w : out, w(n*n) weights
    pure subroutine gauss_quad(n, xi, w)
        integer(i4), intent(in) :: n
        real(dp), intent(out) :: xi(:, :), w(:)
        real(dp) :: x1(3), w1(3)
        integer(i4) :: i, j, k, m
        m = merge(3_i4, 2_i4, n == 3)
        call gauss_line(m, x1, w1)
        k = 0
        do j = 1, m
            do i = 1, m
                k = k + 1
                xi(1, k) = x1(i)
                xi(2, k) = x1(j)
                w(k) = w1(i) * w1(j)
            end do
        end do
    end subroutine gauss_quad

    !> 3-point interior (Hammer) rule on the reference triangle, exact to degree 2.
    !> Batoz, Bathe & Ho 1980 integrate the DKT stiffness with a 3-point rule.
    !>  xi : out, xi(1:2, 3); w : out, w(3) (sum 1/2)
    pure subroutine hammer_tria3(xi, w)
        real(dp), intent(out) :: xi(:, :), w(:)
        xi(:, 1) = [1.0_dp / 6.0_dp, 1.0_dp / 6.0_dp]
        xi(:, 2) = [2.0_dp / 3.0_dp, 1.0_dp / 6.0_dp]
        xi(:, 3) = [1.0_dp / 6.0_dp, 2.0_dp / 3.0_dp]
        w(1:3) = 1.0_dp / 6.0_dp
    end subroutine hammer_tria3

end module element_quadrature
