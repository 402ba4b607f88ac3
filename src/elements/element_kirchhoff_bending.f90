!> Discrete Kirchhoff bending of thin plates in the element's local plane: the DKT triangle
!> (Batoz, Bathe & Ho 1980) and the DKQ quadrilateral (Batoz & Ben Tahar 1982).
!>
!> Local DOF order per corner node: (w, theta_x, theta_y), right-handed rotations about the
!> local axes. The normal-fibre rotations are beta_x = theta_y and beta_y = -theta_x, and the
!> curvatures kappa = (beta_x,x ; beta_y,y ; beta_x,y + beta_y,x); moments M = D_b kappa
!> with D_b = h^3/12 times the plane-stress matrix.
!>
!> Construction (both papers, section 2): beta_x, beta_y are interpolated quadratically
!> (6-node triangle / 8-node serendipity) from the corners and the side midpoints; the
!> midpoint values are eliminated by the discrete Kirchhoff constraints on each side k (i->j,
!> length l, tangent s, normal n):
!>   beta_s(k) = -3/(2l) (w_j - w_i) - (beta_s(i) + beta_s(j)) / 4      (w cubic along s)
!>   beta_n(k) = (beta_n(i) + beta_n(j)) / 2                              (beta_n linear)
!> (Batoz et al. 1980 eqs. 13-16; Batoz & Tahar 1982 eqs. 11-15). Expanding these gives
!> the papers' explicit Hx, Hy functions; here the elimination is done numerically with the
!> same result. Geometry is linear (TRIA3) / bilinear (QUAD4) isoparametric. Integration:
!> 3-point interior rule on the triangle, 2x2 Gauss on the quadrilateral (as in the papers).
module element_kirchhoff_bending
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use element_quadrature, only: gauss_quad, hammer_tria3
    implicit none
    private

    public :: kirchhoff_bending_stiffness, kirchhoff_bending_b, kirchhoff_rotation_map

    !> The rotation map of a cell (rotation_map) is held in fixed (MAP_ROWS, MAP_COLS)
    !> arrays, rows 1:3nn and columns 1:2nn used: no allocation per call (gfortran puts
    !> automatic arrays on the heap), and a caller that evaluates several points of a cell
    !> computes it once (CALC_CHAMP, doc/performance.md).
    integer(i4), parameter, public :: MAP_ROWS = 12, MAP_COLS = 8

contains

    !> Bending stiffness of a DKT (nn = 3) or DKQ (nn = 4) element in its local plane.
    !>  xy   : in, xy(1:2, nn) local node coordinates, counter-clockwise
    !>  nn   : in, 3 or 4
    !>  db   : in, 3x3 bending rigidity (h^3/12 times the plane-stress matrix)
    !>  kb   : out, kb(3nn, 3nn), DOF order (w1, thx1, thy1, w2, ...)
    !>  st   : out, STATUS_MODEL_ERROR for a non-positive Jacobian (clockwise/degenerate)
    subroutine kirchhoff_bending_stiffness(xy, nn, db, kb, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: xy(2, nn), db(3, 3)
        real(dp), intent(out) :: kb(3 * nn, 3 * nn)
        type(status_t), intent(out) :: st
        real(dp) :: xg(2, 4), wg(4), b(3, 3 * nn), det
        integer(i4) :: g, ng
        kb = 0.0_dp
        if (nn == 3) then
            call hammer_tria3(xg, wg)
            ng = 3
        else
            call gauss_quad(2_i4, xg, wg)
            ng = 4
        end if
        do g = 1, ng
            call kirchhoff_bending_b(xy, nn, xg(:, g), b, det)
            if (.not. det > 0.0_dp) then
                call set_error(st, STATUS_MODEL_ERROR, 'plate cell has a non-positive ' // &
                    'Jacobian (degenerate or non-convex cell)')
                return
            end if
            kb = kb + matmul(transpose(b), matmul(db, b)) * (det * wg(g))
        end do
    end subroutine kirchhoff_bending_stiffness

    !> Curvature-displacement matrix B (kappa = B u_b) at a reference point.
    !>  xy  : in, local node coordinates; nn : in, 3 or 4
    !>  xi  : in, reference point (area coordinates (L2, L3) on the triangle, [-1,1]^2 on
    !>        the quadrilateral)
    !>  b   : out, b(3, 3nn); det : out, Jacobian determinant (b = 0 if det <= 0)
    pure subroutine kirchhoff_bending_b(xy, nn, xi, b, det, map_x, map_y)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: xy(2, nn), xi(2)
        real(dp), intent(out) :: b(3, 3 * nn), det
        !> the cell's rotation map (kirchhoff_rotation_map), when the caller has it
        real(dp), intent(in), optional :: map_x(MAP_ROWS, MAP_COLS), map_y(MAP_ROWS, MAP_COLS)
        real(dp) :: bx(MAP_ROWS, MAP_COLS), by(MAP_ROWS, MAP_COLS), dn(2, 8), dg(2, 4)
        real(dp) :: jac(2, 2), dxy(2, 8)
        integer(i4) :: nr
        nr = 2 * nn
        call quadratic_shape_derivatives(nn, xi, dn, dg)
        jac = matmul(dg(:, 1:nn), transpose(xy))
        det = jac(1, 1) * jac(2, 2) - jac(1, 2) * jac(2, 1)
        b = 0.0_dp
        if (.not. det > 0.0_dp) return
        dxy(1, 1:nr) = (jac(2, 2) * dn(1, 1:nr) - jac(1, 2) * dn(2, 1:nr)) / det
        dxy(2, 1:nr) = (-jac(2, 1) * dn(1, 1:nr) + jac(1, 1) * dn(2, 1:nr)) / det
        if (present(map_x) .and. present(map_y)) then
            call add_rotation_gradients(nn, dxy, map_x, map_y, b)
        else
            call rotation_map(xy, nn, bx, by)
            call add_rotation_gradients(nn, dxy, bx, by, b)
        end if
    end subroutine kirchhoff_bending_b

    ! b += the x, y derivatives of the rotation map: kappa = (beta_x,x ; beta_y,y ;
    ! beta_x,y + beta_y,x), dxy the derivatives of the 2nn rotation shape functions. Column
    ! by column, each entry summed over the rotation nodes a = 1, 2, ... in turn.
    pure subroutine add_rotation_gradients(nn, dxy, bx, by, b)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: dxy(2, 8), bx(MAP_ROWS, MAP_COLS), by(MAP_ROWS, MAP_COLS)
        real(dp), intent(inout) :: b(3, 3 * nn)
        real(dp) :: b1, b2, b3
        integer(i4) :: a, j
        do j = 1, 3 * nn
            b1 = b(1, j)
            b2 = b(2, j)
            b3 = b(3, j)
            do a = 1, 2 * nn
                b1 = b1 + dxy(1, a) * bx(j, a)
                b2 = b2 + dxy(2, a) * by(j, a)
                b3 = b3 + dxy(2, a) * bx(j, a) + dxy(1, a) * by(j, a)
            end do
            b(1, j) = b1
            b(2, j) = b2
            b(3, j) = b3
        end do
    end subroutine add_rotation_gradients

    !> The rotation map below, for the stress recovery (element_plate_fields: the shear
    !> forces need the second derivatives of the rotation field).
    pure subroutine kirchhoff_rotation_map(xy, nn, bx, by)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: xy(2, nn)
        real(dp), intent(out) :: bx(MAP_ROWS, MAP_COLS), by(MAP_ROWS, MAP_COLS)
        call rotation_map(xy, nn, bx, by)
    end subroutine kirchhoff_rotation_map

    !> beta_x, beta_y at the corners and side midpoints as linear forms of the element DOFs:
    !> column a of bx/by holds the coefficients of beta_x/beta_y at rotation node a (corners
    !> 1..nn, then midpoints of sides 1-2, 2-3, ..., nn-1), rows 1:3nn (the rest 0).
    pure subroutine rotation_map(xy, nn, bx, by)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: xy(2, nn)
        real(dp), intent(out) :: bx(MAP_ROWS, MAP_COLS), by(MAP_ROWS, MAP_COLS)
        real(dp) :: d(2), length, c, s
        real(dp) :: bs_i(MAP_ROWS), bs_j(MAP_ROWS), bn_i(MAP_ROWS), bn_j(MAP_ROWS)
        real(dp) :: bs(MAP_ROWS), bn(MAP_ROWS)
        integer(i4) :: i, j, k, m
        m = 3 * nn
        bx = 0.0_dp
        by = 0.0_dp
        do i = 1, nn
            bx(3 * i, i) = 1.0_dp            ! beta_x = theta_y
            by(3 * i - 1, i) = -1.0_dp       ! beta_y = -theta_x
        end do
        do k = 1, nn
            i = k
            j = mod(k, nn) + 1
            d = xy(:, j) - xy(:, i)
            length = norm2(d)
            if (.not. length > 0.0_dp) cycle   ! degenerate: caught by the Jacobian check
            c = d(1) / length
            s = d(2) / length
            bs_i(1:m) = c * bx(1:m, i) + s * by(1:m, i)
            bs_j(1:m) = c * bx(1:m, j) + s * by(1:m, j)
            bn_i(1:m) = s * bx(1:m, i) - c * by(1:m, i)
            bn_j(1:m) = s * bx(1:m, j) - c * by(1:m, j)
            bs(1:m) = -0.25_dp * (bs_i(1:m) + bs_j(1:m))
            bs(3 * j - 2) = bs(3 * j - 2) - 1.5_dp / length
            bs(3 * i - 2) = bs(3 * i - 2) + 1.5_dp / length
            bn(1:m) = 0.5_dp * (bn_i(1:m) + bn_j(1:m))
            bx(1:m, nn + k) = c * bs(1:m) + s * bn(1:m)
            by(1:m, nn + k) = s * bs(1:m) - c * bn(1:m)
        end do
    end subroutine rotation_map

    !> Derivatives (d/dxi, d/deta) of the quadratic rotation shape functions dn(:, 1:2nn)
    !> (6-node triangle or 8-node serendipity) and of the linear/bilinear geometry
    !> functions dg(:, 1:nn).
    pure subroutine quadratic_shape_derivatives(nn, xi, dn, dg)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: xi(2)
        real(dp), intent(out) :: dn(2, 8), dg(2, 4)
        real(dp), parameter :: xc(4) = [-1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp]
        real(dp), parameter :: yc(4) = [-1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp]
        real(dp) :: l(3), dl(2, 3), x, y
        integer(i4) :: i, j
        dn = 0.0_dp
        dg = 0.0_dp
        if (nn == 3) then
            l = [1.0_dp - xi(1) - xi(2), xi(1), xi(2)]
            dl(:, 1) = [-1.0_dp, -1.0_dp]
            dl(:, 2) = [1.0_dp, 0.0_dp]
            dl(:, 3) = [0.0_dp, 1.0_dp]
            dg(:, 1:3) = dl
            do i = 1, 3
                j = mod(i, 3_i4) + 1
                dn(:, i) = (4.0_dp * l(i) - 1.0_dp) * dl(:, i)
                dn(:, 3 + i) = 4.0_dp * (dl(:, i) * l(j) + l(i) * dl(:, j))
            end do
            return
        end if
        x = xi(1)
        y = xi(2)
        do i = 1, 4
            dg(1, i) = 0.25_dp * xc(i) * (1.0_dp + yc(i) * y)
            dg(2, i) = 0.25_dp * yc(i) * (1.0_dp + xc(i) * x)
            dn(1, i) = 0.25_dp * xc(i) * (1.0_dp + yc(i) * y) * (2.0_dp * xc(i) * x + yc(i) * y)
            dn(2, i) = 0.25_dp * yc(i) * (1.0_dp + xc(i) * x) * (xc(i) * x + 2.0_dp * yc(i) * y)
        end do
        ! Midpoints of sides 1-2 (eta = -1) and 3-4 (eta = +1).
        dn(:, 5) = [-x * (1.0_dp - y), -0.5_dp * (1.0_dp - x * x)]
        dn(:, 7) = [-x * (1.0_dp + y), 0.5_dp * (1.0_dp - x * x)]
        ! Midpoints of sides 2-3 (xi = +1) and 4-1 (xi = -1).
        dn(:, 6) = [0.5_dp * (1.0_dp - y * y), -y * (1.0_dp + x)]
        dn(:, 8) = [-0.5_dp * (1.0_dp - y * y), -y * (1.0_dp - x)]
    end subroutine quadratic_shape_derivatives

end module element_kirchhoff_bending
