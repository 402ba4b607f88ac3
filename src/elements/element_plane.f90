!> The plane element family for D_PLAN (plane strain) and C_PLAN (plane stress): one
!> isoparametric implementation on TRIA3, TRIA6, QUAD4, QUAD8 and QUAD9, unit depth, 2 DOF
!> per node (DX, DY), element vectors node by node (DX1, DY1, DX2, ...). Each cell type is
!> integrated with Code_Aster's RIGI family (element_gauss_families: TRIA3 1 point, TRIA6
!> 3, QUAD4 2x2, QUAD8 and QUAD9 3x3), and strains and stresses are given at the points of
!> any family, so ELGA fields mean what Code_Aster's mean.
!>
!> K = sum_g B^T D B |det J| w_g, with the shape-function derivatives taken with the signed
!> det J (Code_Aster's dfdm2d): a clockwise cell is the same element as its
!> counter-clockwise renumbering (SSNL130 B's MED mesh has clockwise QUAD4). A cell whose
!> det J is (relatively) zero at a point of its rule, or of both signs (coincident or
!> aligned nodes, a folded, non-convex or inverted cell, a middle node beyond the quarter
!> of its side) is refused.
!>
!> The law (plane_law_t): the 3D stiffness on (xx, yy, zz, xy) and the in-plane matrix D
!> (3x3 on xx, yy and the engineering shear): D_PLAN restrains eps_zz (sig_zz follows),
!> C_PLAN frees it (sig_zz = 0; D by static condensation of zz). Thermal (or any initial)
!> strains eps0 load the element through int B^T sig0: in D_PLAN the restrained
!> out-of-plane expansion adds its share (Code_Aster's D_PLAN: sig = D4 (eps - eps0) with
!> eps_zz = 0).
!> References: Zienkiewicz & Taylor, The Finite Element Method vol. 1, ch. 6 and 9;
!> Code_Aster R3.01.01 (isoparametric elements), R4.01.02 (plane strain / stress).
module element_plane
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use mesh_cell_shapes, only: CELL_TRIA3, CELL_QUAD4, CELL_TYPE_NAMES, CELL_TYPE_NODES, &
        CELL_TYPE_CORNERS, CELL_TYPE_DIM, MAX_CELL_NODES, cell_shape
    use element_gauss_families, only: gauss_rule_t, gauss_family, FORMULATION_PLANE, &
        MAX_GAUSS_POINTS
    implicit none
    private

    !> Most equations of a plane element (QUAD9: 9 nodes x 2).
    integer(i4), parameter, public :: MAX_PLANE_DOFS = 2 * MAX_CELL_NODES

    !> A det J below this fraction of the cell's squared size is zero: the cell has
    !> collapsed (~1e3 machine epsilons, the threshold element_plate uses for a plate cell's
    !> area).
    real(dp), parameter :: JACOBIAN_ZERO = 1.0e3_dp * epsilon(1.0_dp)

    !> A plane elastic law (module header).
    type, public :: plane_law_t
        logical :: plane_strain = .true.     !< D_PLAN; .false. for C_PLAN
        real(dp) :: d4(4, 4) = 0.0_dp        !< 3D stiffness on (xx, yy, zz, xy engineering)
        real(dp) :: d3(3, 3) = 0.0_dp        !< in-plane matrix on (xx, yy, xy engineering)
    end type plane_law_t

    public :: plane_elasticity_matrix, plane_law_isotropic, plane_law_from_d4, &
        plane_stiffness, plane_internal_forces, plane_point_state, plane_initial_strain_forces, &
        plane_derivatives, plane_rigi_rule, check_plane_jacobians

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
        type(plane_law_t) :: law
        call plane_law_isotropic(young, nu, plane_strain, law, st)
        dmat = law%d3
    end subroutine plane_elasticity_matrix

    !> The plane law of an isotropic material.
    !>  st : out, STATUS_MODEL_ERROR if E <= 0 or nu outside (-1, 0.5)
    subroutine plane_law_isotropic(young, nu, plane_strain, law, st)
        real(dp), intent(in) :: young, nu
        logical, intent(in) :: plane_strain
        type(plane_law_t), intent(out) :: law
        type(status_t), intent(out) :: st
        real(dp) :: c, lambda, mu
        law%plane_strain = plane_strain
        if (young <= 0.0_dp .or. nu <= -1.0_dp .or. nu >= 0.5_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'ELAS: need E > 0 and -1 < NU < 0.5')
            return
        end if
        lambda = young * nu / ((1.0_dp + nu) * (1.0_dp - 2.0_dp * nu))
        mu = young / (2.0_dp * (1.0_dp + nu))
        law%d4(1:3, 1:3) = lambda
        law%d4(1, 1) = lambda + 2.0_dp * mu
        law%d4(2, 2) = law%d4(1, 1)
        law%d4(3, 3) = law%d4(1, 1)
        law%d4(4, 4) = mu
        ! the in-plane matrix in closed form (the same digits as the condensation gives)
        if (plane_strain) then
            c = young / ((1.0_dp + nu) * (1.0_dp - 2.0_dp * nu))
            law%d3(1, 1) = c * (1.0_dp - nu)
            law%d3(2, 2) = law%d3(1, 1)
            law%d3(1, 2) = c * nu
            law%d3(3, 3) = c * (1.0_dp - 2.0_dp * nu) / 2.0_dp
        else
            c = young / (1.0_dp - nu * nu)
            law%d3(1, 1) = c
            law%d3(2, 2) = c
            law%d3(1, 2) = c * nu
            law%d3(3, 3) = c * (1.0_dp - nu) / 2.0_dp
        end if
        law%d3(2, 1) = law%d3(1, 2)
    end subroutine plane_law_isotropic

    !> The plane law of any 3D stiffness on (xx, yy, zz, xy): D_PLAN keeps its in-plane
    !> block, C_PLAN condenses zz out (sig_zz = 0).
    !>  st : out, STATUS_MODEL_ERROR if d4(3, 3) <= 0 in C_PLAN
    subroutine plane_law_from_d4(d4, plane_strain, law, st)
        real(dp), intent(in) :: d4(4, 4)
        logical, intent(in) :: plane_strain
        type(plane_law_t), intent(out) :: law
        type(status_t), intent(out) :: st
        integer(i4), parameter :: IN_PLANE(3) = [1, 2, 4]
        integer(i4) :: i, j
        law%plane_strain = plane_strain
        law%d4 = d4
        do j = 1, 3
            do i = 1, 3
                law%d3(i, j) = d4(IN_PLANE(i), IN_PLANE(j))
                if (.not. plane_strain .and. d4(3, 3) > 0.0_dp) law%d3(i, j) = law%d3(i, j) &
                    - d4(IN_PLANE(i), 3) * d4(3, IN_PLANE(j)) / d4(3, 3)
            end do
        end do
        if (.not. plane_strain .and. .not. d4(3, 3) > 0.0_dp) call set_error(st, &
            STATUS_MODEL_ERROR, 'C_PLAN: the material has no stiffness across the plane')
    end subroutine plane_law_from_d4

    !> The points of Code_Aster's RIGI family of a plane cell type.
    subroutine plane_rigi_rule(ctype, rule, st)
        integer(i4), intent(in) :: ctype
        type(gauss_rule_t), intent(out) :: rule
        type(status_t), intent(out) :: st
        call gauss_family(FORMULATION_PLANE, ctype, 'RIGI', rule, st)
    end subroutine plane_rigi_rule

    !> Jacobian and x/y derivatives of the shape functions at one reference point.
    !>  ctype   : in, CELL_* (a surface type)
    !>  xy      : in, xy(2, nn) node coordinates
    !>  xi, eta : in, the reference point
    !>  n       : out, n(nn) shape functions
    !>  dxy     : out, dxy(2, nn) d/dx, d/dy (0 when det = 0)
    !>  det     : out, the signed Jacobian determinant
    pure subroutine plane_derivatives(ctype, xy, xi, eta, n, dxy, det)
        integer(i4), intent(in) :: ctype
        real(dp), intent(in) :: xy(:, :), xi, eta
        real(dp), intent(out) :: n(:), dxy(:, :), det
        real(dp) :: dn(2, MAX_CELL_NODES), jac(2, 2)
        integer(i4) :: nn
        nn = CELL_TYPE_NODES(ctype)
        call cell_shape(ctype, xi, eta, n(1:nn), dn(:, 1:nn))
        jac = matmul(dn(:, 1:nn), transpose(xy(1:2, 1:nn)))      ! J(i, j) = d x_j / d xi_i
        det = jac(1, 1) * jac(2, 2) - jac(1, 2) * jac(2, 1)
        dxy(:, 1:nn) = 0.0_dp
        if (.not. abs(det) > 0.0_dp) return
        dxy(1, 1:nn) = (jac(2, 2) * dn(1, 1:nn) - jac(1, 2) * dn(2, 1:nn)) / det
        dxy(2, 1:nn) = (-jac(2, 1) * dn(1, 1:nn) + jac(1, 1) * dn(2, 1:nn)) / det
    end subroutine plane_derivatives

    !> Refuses a cell whose det J is zero or of both signs at the points of `rule`.
    !>  det : in, the determinants at the points
    !>  st  : out, STATUS_MODEL_ERROR naming the cell type and what is wrong
    subroutine check_plane_jacobians(ctype, xy, det, st)
        integer(i4), intent(in) :: ctype
        real(dp), intent(in) :: xy(:, :), det(:)
        type(status_t), intent(out) :: st
        real(dp) :: size2
        integer(i4) :: i, j, nc
        nc = CELL_TYPE_CORNERS(ctype)
        if (nc == 4) then
            size2 = max(sum((xy(:, 3) - xy(:, 1))**2), sum((xy(:, 4) - xy(:, 2))**2))
        else
            size2 = 0.0_dp
            do i = 1, nc - 1
                do j = i + 1, nc
                    size2 = max(size2, sum((xy(:, j) - xy(:, i))**2))
                end do
            end do
        end if
        if (.not. minval(abs(det)) > JACOBIAN_ZERO * size2 .or. &
            (any(det > 0.0_dp) .and. any(det < 0.0_dp))) then
            call set_error(st, STATUS_MODEL_ERROR, trim(CELL_TYPE_NAMES(ctype)) // ' cell ' // &
                'is degenerate: its Jacobian is zero or changes sign inside it (coincident ' &
                // 'or aligned nodes, or a folded, non-convex or inverted cell)')
        end if
    end subroutine check_plane_jacobians

    ! Strain-displacement matrix (eps_xx, eps_yy, gamma_xy) from the x/y derivatives.
    pure subroutine plane_b(nn, dxy, b)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: dxy(:, :)
        real(dp), intent(out) :: b(:, :)
        integer(i4) :: i
        b(1:3, 1:2 * nn) = 0.0_dp
        do i = 1, nn
            b(1, 2 * i - 1) = dxy(1, i)
            b(2, 2 * i) = dxy(2, i)
            b(3, 2 * i - 1) = dxy(2, i)
            b(3, 2 * i) = dxy(1, i)
        end do
    end subroutine plane_b

    ! The B matrices and weights |det J| w at the points of the RIGI rule, checked.
    subroutine rigi_b_matrices(ctype, xy, nn, ng, b, wdet, st)
        integer(i4), intent(in) :: ctype
        real(dp), intent(in) :: xy(:, :)
        integer(i4), intent(out) :: nn, ng
        real(dp), intent(out) :: b(3, MAX_PLANE_DOFS, MAX_GAUSS_POINTS), wdet(MAX_GAUSS_POINTS)
        type(status_t), intent(out) :: st
        type(gauss_rule_t) :: rule
        real(dp) :: n(MAX_CELL_NODES), dxy(2, MAX_CELL_NODES), det(MAX_GAUSS_POINTS)
        integer(i4) :: g
        nn = CELL_TYPE_NODES(ctype)
        ng = 0
        if (CELL_TYPE_DIM(ctype) /= 2) then
            call set_error(st, STATUS_MODEL_ERROR, 'a plane element needs a surface cell, ' &
                // 'not a ' // trim(CELL_TYPE_NAMES(ctype)))
            return
        end if
        call plane_rigi_rule(ctype, rule, st)
        if (st%failed()) return
        ng = rule%n
        do g = 1, ng
            call plane_derivatives(ctype, xy, rule%xi(1, g), rule%xi(2, g), n, dxy, det(g))
            call plane_b(nn, dxy, b(:, :, g))
            wdet(g) = abs(det(g)) * rule%w(g)
        end do
        call check_plane_jacobians(ctype, xy, det(1:ng), st)
    end subroutine rigi_b_matrices

    !> Stiffness of a plane element for a given in-plane matrix D (unit depth; the caller
    !> scales D for a plate's thickness): K = sum_g B^T D B |det J| w_g on the RIGI rule.
    !>  ctype : in, CELL_TRIA3, TRIA6, QUAD4, QUAD8 or QUAD9
    !>  xy    : in, xy(2, nn) node coordinates in the plane (either orientation)
    !>  dmat  : in, 3x3 constitutive matrix on (xx, yy, xy engineering)
    !>  ke    : out, ke(2 nn, 2 nn), DOF order (u1, v1, u2, v2, ...)
    !>  st    : out, STATUS_MODEL_ERROR for a degenerate cell (check_plane_jacobians)
    subroutine plane_stiffness(ctype, xy, dmat, ke, st)
        integer(i4), intent(in) :: ctype
        real(dp), intent(in) :: xy(:, :), dmat(3, 3)
        real(dp), intent(out) :: ke(:, :)
        type(status_t), intent(out) :: st
        real(dp) :: b(3, MAX_PLANE_DOFS, MAX_GAUSS_POINTS), wdet(MAX_GAUSS_POINTS)
        real(dp) :: db(3, MAX_PLANE_DOFS)
        integer(i4) :: nn, ng, g, nd
        ke = 0.0_dp
        call rigi_b_matrices(ctype, xy, nn, ng, b, wdet, st)
        if (st%failed()) return
        nd = 2 * nn
        do g = 1, ng
            db(:, 1:nd) = matmul(dmat, b(:, 1:nd, g)) * wdet(g)
            ke(1:nd, 1:nd) = ke(1:nd, 1:nd) + matmul(transpose(b(:, 1:nd, g)), db(:, 1:nd))
        end do
    end subroutine plane_stiffness

    !> Internal forces f = K u of a plane element (linear elasticity).
    !>  ue : in, ue(2 nn); fe : out, fe(2 nn); other arguments as plane_stiffness
    subroutine plane_internal_forces(ctype, xy, dmat, ue, fe, st)
        integer(i4), intent(in) :: ctype
        real(dp), intent(in) :: xy(:, :), dmat(3, 3), ue(:)
        real(dp), intent(out) :: fe(:)
        type(status_t), intent(out) :: st
        real(dp) :: ke(MAX_PLANE_DOFS, MAX_PLANE_DOFS)
        integer(i4) :: nd
        nd = 2 * CELL_TYPE_NODES(ctype)
        fe = 0.0_dp
        call plane_stiffness(ctype, xy, dmat, ke(1:nd, 1:nd), st)
        if (st%failed()) return
        fe(1:nd) = matmul(ke(1:nd, 1:nd), ue(1:nd))
    end subroutine plane_internal_forces

    !> Nodal forces of an initial strain field eps0 (thermal strains, PRE_EPSI):
    !> f = sum_g B^T sig0 |det J| w_g on the RIGI rule, sig0 = the in-plane stress the law
    !> gives to eps0 (D_PLAN: D4 eps0, the restrained zz expansion included; C_PLAN:
    !> D eps0 in the plane, zz free). The element's equilibrium is K u = f_ext + f.
    !>  eps0 : in, eps0(4, ng) (xx, yy, zz, xy engineering) at the RIGI points
    !>  fe   : out, fe(2 nn)
    subroutine plane_initial_strain_forces(ctype, xy, law, eps0, fe, st)
        integer(i4), intent(in) :: ctype
        real(dp), intent(in) :: xy(:, :), eps0(:, :)
        type(plane_law_t), intent(in) :: law
        real(dp), intent(out) :: fe(:)
        type(status_t), intent(out) :: st
        real(dp) :: b(3, MAX_PLANE_DOFS, MAX_GAUSS_POINTS), wdet(MAX_GAUSS_POINTS), sig0(3)
        integer(i4) :: nn, ng, g, nd
        fe = 0.0_dp
        call rigi_b_matrices(ctype, xy, nn, ng, b, wdet, st)
        if (st%failed()) return
        nd = 2 * nn
        do g = 1, ng
            sig0 = initial_stress(law, eps0(:, g))
            fe(1:nd) = fe(1:nd) + matmul(transpose(b(:, 1:nd, g)), sig0) * wdet(g)
        end do
    end subroutine plane_initial_strain_forces

    ! The in-plane stress (xx, yy, xy) a law gives to a strain eps0 acting alone.
    pure function initial_stress(law, eps0) result(sig)
        type(plane_law_t), intent(in) :: law
        real(dp), intent(in) :: eps0(4)
        real(dp) :: sig(3), s4(4)
        if (law%plane_strain) then
            s4 = matmul(law%d4, eps0)
            sig = [s4(1), s4(2), s4(4)]
        else
            sig = matmul(law%d3, [eps0(1), eps0(2), eps0(4)])
        end if
    end function initial_stress

    !> Strains and stresses at the points of a rule, in Code_Aster's components:
    !> eps = (EPXX, EPYY, EPZZ, EPXY) with EPXY = gamma_xy / 2, sig = (SIXX, SIYY, SIZZ,
    !> SIXY). D_PLAN: EPZZ = 0 and SIZZ from the restraint; C_PLAN: SIZZ = 0 and EPZZ from
    !> it. With eps0 (thermal strains), sig = D4 (eps - eps0) and eps is the total strain.
    !>  rule : in, the points (any family of the cell type)
    !>  ue   : in, ue(2 nn)
    !>  eps0 : in, optional, eps0(4, rule%n) initial strains (engineering xy)
    !>  sig, eps : out, (4, rule%n)
    !>  st   : out, STATUS_MODEL_ERROR for a degenerate cell
    subroutine plane_point_state(ctype, xy, law, ue, rule, sig, eps, st, eps0)
        integer(i4), intent(in) :: ctype
        real(dp), intent(in) :: xy(:, :), ue(:)
        type(plane_law_t), intent(in) :: law
        type(gauss_rule_t), intent(in) :: rule
        real(dp), intent(out) :: sig(:, :), eps(:, :)
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: eps0(:, :)
        real(dp) :: n(MAX_CELL_NODES), dxy(2, MAX_CELL_NODES), det(MAX_GAUSS_POINTS)
        real(dp) :: b(3, MAX_PLANE_DOFS), e3(3), e4(4), e0(4), s4(4)
        integer(i4) :: nn, g
        nn = CELL_TYPE_NODES(ctype)
        do g = 1, rule%n
            call plane_derivatives(ctype, xy, rule%xi(1, g), rule%xi(2, g), n, dxy, det(g))
            call plane_b(nn, dxy, b)
            e3 = matmul(b(:, 1:2 * nn), ue(1:2 * nn))
            e0 = 0.0_dp
            if (present(eps0)) e0 = eps0(:, g)
            e4 = [e3(1), e3(2), 0.0_dp, e3(3)]
            if (law%plane_strain) then
                s4 = matmul(law%d4, e4 - e0)
            else
                ! sig_zz = 0 fixes eps_zz: d4(3,:) (eps - eps0) = 0
                e4(3) = e0(3) - (law%d4(3, 1) * (e4(1) - e0(1)) + law%d4(3, 2) * (e4(2) - &
                    e0(2)) + law%d4(3, 4) * (e4(4) - e0(4))) / law%d4(3, 3)
                s4 = matmul(law%d4, e4 - e0)
                s4(3) = 0.0_dp
            end if
            eps(:, g) = [e4(1), e4(2), e4(3), 0.5_dp * e4(4)]
            sig(:, g) = s4
        end do
        if (rule%n > 0) call check_plane_jacobians(ctype, xy, det(1:rule%n), st)
    end subroutine plane_point_state

end module element_plane
