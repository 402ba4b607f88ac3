!> Bilinear 4-node quadrilateral for plane strain (D_PLAN) and plane stress (C_PLAN).
!>
!> 2 DOF per node (DX, DY), element vector ordered node by node: (DX1, DY1, DX2, DY2, ...).
!> Isoparametric bilinear interpolation, full 2x2 Gauss integration, unit depth (the
!> stiffness is per unit length in z). Reference corners (-1,-1), (1,-1), (1,1), (-1,1).
!> Reference: Zienkiewicz & Taylor, The Finite Element Method vol. 1, ch. 6 (isoparametric
!> Q4). The membrane routine is shared with the plates.
!> Node order: counter-clockwise or clockwise. As Code_Aster (dfdm2d: derivatives with the
!> signed Jacobian determinant, weight |det J| w), a clockwise cell gives the same matrix as
!> its counter-clockwise renumbering (SSNL130 B's MED mesh has clockwise QUAD4). A cell
!> whose Jacobian vanishes or changes sign between Gauss points (coincident or aligned
!> nodes, a folded or non-convex cell) is refused.
module element_plane_quad4
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use element_quadrature, only: gauss_quad
    implicit none
    private

    public :: plane_elasticity_matrix, quad4_shape, membrane_quad4_stiffness
    public :: plane_quad4_stiffness, plane_quad4_internal_forces

    !> A Jacobian determinant below this fraction of the cell's squared size (its longer
    !> diagonal squared) is zero: the cell has collapsed (~1e3 machine epsilons, the
    !> threshold element_plate uses for a plate cell's area).
    real(dp), parameter :: JACOBIAN_ZERO = 1.0e3_dp * epsilon(1.0_dp)

contains

    !> Isotropic plane elasticity matrix D (stress = D strain, engineering shear strain).
    !>  young, nu    : in, Young's modulus and Poisson's ratio
    !>  plane_strain : in, .true. for D_PLAN (eps_zz = 0), .false. for C_PLAN (sig_zz = 0)
    !>  dmat         : out, 3x3 matrix for (xx, yy, xy)
    !>  st           : out, STATUS_MODEL_ERROR if E <= 0 or nu outside (-1, 0.5)
    subroutine plane_elasticity_matrix(young, nu, plane_strain, dmat, st)
        real(dp), intent(in) :: young, nu
        logical, intent(in) :: plane_strain
        real(dp), intent(out) :: dmat(3, 3)
        type(status_t), intent(out) :: st
        real(dp) :: c
        dmat = 0.0_dp
        if (young <= 0.0_dp .or. nu <= -1.0_dp .or. nu >= 0.5_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'ELAS: need E > 0 and -1 < NU < 0.5')
            return
        end if
        if (plane_strain) then
            c = young / ((1.0_dp + nu) * (1.0_dp - 2.0_dp * nu))
            dmat(1, 1) = c * (1.0_dp - nu)
            dmat(2, 2) = dmat(1, 1)
            dmat(1, 2) = c * nu
            dmat(3, 3) = c * (1.0_dp - 2.0_dp * nu) / 2.0_dp
        else
            c = young / (1.0_dp - nu * nu)
            dmat(1, 1) = c
            dmat(2, 2) = c
            dmat(1, 2) = c * nu
            dmat(3, 3) = c * (1.0_dp - nu) / 2.0_dp
        end if
        dmat(2, 1) = dmat(1, 2)
    end subroutine plane_elasticity_matrix

    !> Bilinear shape functions and their derivatives at (xi, eta).
    !>  xi, eta : in, reference coordinates in [-1,1]
    !>  n       : out, n(4) shape functions; dn : out, dn(1:2, 4) d/dxi, d/deta
    pure subroutine quad4_shape(xi, eta, n, dn)
        real(dp), intent(in) :: xi, eta
        real(dp), intent(out) :: n(4), dn(2, 4)
        real(dp), parameter :: xn(4) = [-1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp]
        real(dp), parameter :: yn(4) = [-1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp]
        integer(i4) :: i
        do i = 1, 4
            n(i) = 0.25_dp * (1.0_dp + xn(i) * xi) * (1.0_dp + yn(i) * eta)
            dn(1, i) = 0.25_dp * xn(i) * (1.0_dp + yn(i) * eta)
            dn(2, i) = 0.25_dp * yn(i) * (1.0_dp + xn(i) * xi)
        end do
    end subroutine quad4_shape

    !> Stiffness of a bilinear quadrilateral in its plane for a given D (2x2 Gauss):
    !> K = sum_g B^T D B detJ w_g. The caller scales D (depth 1, or the plate thickness).
    !>  xy   : in, xy(1:2, 4) node coordinates in the plane (either orientation)
    !>  dmat : in, 3x3 constitutive matrix (per unit depth)
    !>  km   : out, 8x8 stiffness, DOF order (u1, v1, u2, v2, ...)
    !>  st   : out, STATUS_MODEL_ERROR if det J is zero (below JACOBIAN_ZERO of the cell's
    !>         squared size) or changes sign at the Gauss points (a degenerate cell)
    subroutine membrane_quad4_stiffness(xy, dmat, km, st)
        real(dp), intent(in) :: xy(2, 4), dmat(3, 3)
        real(dp), intent(out) :: km(8, 8)
        type(status_t), intent(out) :: st
        real(dp) :: xg(2, 4), wg(4), n(4), dn(2, 4), jac(2, 2), det(4), dxy(2, 4, 4), b(3, 8)
        real(dp) :: size2
        integer(i4) :: g
        km = 0.0_dp
        call gauss_quad(2_i4, xg, wg)
        do g = 1, 4
            call quad4_shape(xg(1, g), xg(2, g), n, dn)
            call physical_derivatives(xy, dn, jac, det(g), dxy(:, :, g))
        end do
        size2 = max(sum((xy(:, 3) - xy(:, 1))**2), sum((xy(:, 4) - xy(:, 2))**2))
        if (.not. minval(abs(det)) > JACOBIAN_ZERO * size2 .or. &
            (any(det > 0.0_dp) .and. any(det < 0.0_dp))) then
            call set_error(st, STATUS_MODEL_ERROR, 'QUAD4 cell is degenerate: its ' // &
                'Jacobian is zero or changes sign inside it (coincident or aligned nodes, ' // &
                'or a folded or non-convex cell)')
            return
        end if
        do g = 1, 4
            call membrane_b(dxy(:, :, g), b)
            km = km + matmul(transpose(b), matmul(dmat, b)) * (abs(det(g)) * wg(g))
        end do
    end subroutine membrane_quad4_stiffness

    !> Stiffness of a D_PLAN / C_PLAN QUAD4 (unit depth).
    !>  coords : in, coords(1:2, 4) node coordinates (x, y)
    !>  young, nu, plane_strain : in, see plane_elasticity_matrix
    !>  ke     : out, 8x8 stiffness (DX1, DY1, ..., DX4, DY4)
    !>  st     : out, material or Jacobian error
    subroutine plane_quad4_stiffness(coords, young, nu, plane_strain, ke, st)
        real(dp), intent(in) :: coords(2, 4), young, nu
        logical, intent(in) :: plane_strain
        real(dp), intent(out) :: ke(8, 8)
        type(status_t), intent(out) :: st
        real(dp) :: dmat(3, 3)
        ke = 0.0_dp
        call plane_elasticity_matrix(young, nu, plane_strain, dmat, st)
        if (st%failed()) return
        call membrane_quad4_stiffness(coords, dmat, ke, st)
    end subroutine plane_quad4_stiffness

    !> Internal forces f = K u of a D_PLAN / C_PLAN QUAD4 (linear elasticity).
    !>  coords, young, nu, plane_strain : in, as plane_quad4_stiffness
    !>  ue : in, ue(8) element displacements; fe : out, fe(8) internal forces
    !>  st : out, as plane_quad4_stiffness
    subroutine plane_quad4_internal_forces(coords, young, nu, plane_strain, ue, fe, st)
        real(dp), intent(in) :: coords(2, 4), young, nu, ue(8)
        logical, intent(in) :: plane_strain
        real(dp), intent(out) :: fe(8)
        type(status_t), intent(out) :: st
        real(dp) :: ke(8, 8)
        fe = 0.0_dp
        call plane_quad4_stiffness(coords, young, nu, plane_strain, ke, st)
        if (st%failed()) return
        fe = matmul(ke, ue)
    end subroutine plane_quad4_internal_forces

    !> Jacobian J(i,j) = d x_j / d xi_i, its (signed) determinant and the x/y derivatives of
    !> the shape functions (dxy = J^-1 dn; 0 when det = 0).
    pure subroutine physical_derivatives(xy, dn, jac, det, dxy)
        real(dp), intent(in) :: xy(2, 4), dn(2, 4)
        real(dp), intent(out) :: jac(2, 2), det, dxy(2, 4)
        jac = matmul(dn, transpose(xy))
        det = jac(1, 1) * jac(2, 2) - jac(1, 2) * jac(2, 1)
        dxy = 0.0_dp
        if (.not. abs(det) > 0.0_dp) return
        dxy(1, :) = (jac(2, 2) * dn(1, :) - jac(1, 2) * dn(2, :)) / det
        dxy(2, :) = (-jac(2, 1) * dn(1, :) + jac(1, 1) * dn(2, :)) / det
    end subroutine physical_derivatives

    !> Strain-displacement matrix (eps_xx, eps_yy, gamma_xy) of a 4-node membrane.
    pure subroutine membrane_b(dxy, b)
        real(dp), intent(in) :: dxy(2, 4)
        real(dp), intent(out) :: b(3, 8)
        integer(i4) :: i
        b = 0.0_dp
        do i = 1, 4
            b(1, 2 * i - 1) = dxy(1, i)
            b(2, 2 * i) = dxy(2, i)
            b(3, 2 * i - 1) = dxy(2, i)
            b(3, 2 * i) = dxy(1, i)
        end do
    end subroutine membrane_b

end module element_plane_quad4
