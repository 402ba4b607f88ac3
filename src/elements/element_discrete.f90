!> Discrete translational springs: DIS_T (3D) and 2D_DIS_T (2D) on SEG2 and POI1 cells,
!> characteristics K_T_D_L (SEG2) and K_T_D_N (POI1), frame REPERE = 'LOCAL' or 'GLOBAL'.
!>
!> DOF order: DIS_T SEG2 (DX1, DY1, DZ1, DX2, DY2, DZ2); POI1 (DX, DY, DZ); 2D_DIS_T SEG2
!> (DX1, DY1, DX2, DY2); POI1 (DX, DY). All matrices are returned in the GLOBAL frame.
!>
!> Local frame (Code_Aster convention, R4.01.01 / ORIENTATION of AFFE_CARA_ELEM): the
!> rotation matrix P (rows = local axes in global components, u_local = P u_global) is built
!> from nautical angles (alpha, beta, gamma):
!>   P = Rx(gamma) Ry(beta) Rz(alpha) with, for a segment, alpha = atan2(vy, vx),
!>   beta = -atan2(vz, sqrt(vx^2 + vy^2)) (alpha = 0 when the segment is vertical) and
!>   gamma = ANGL_VRIL, v = node 1 -> node 2. Local x is then along v; for gamma = 0 the
!>   local y is horizontal (in the global XY plane). In 2D the local x is along v and
!>   local y = z x local x.
!> SEG2 matrix (Code_Aster K_T_D_L): [[K, -K], [-K, K]] with K = P^T diag(k) P.
!>
!> Any other discrete (DIS_TR, 2D_DIS_TR, full matrices K_T_N, K_T_L, K_TR_N, K_TR_L) goes
!> through the general pair discrete_local_matrix / discrete_rotate_to_global: the element
!> matrix in the discrete's frame (a diagonal characteristic gives diag(k) on a node and
!> [[K, -K], [-K, K]] on a link; a full one is the matrix itself), then
!> K_global = T^T K_local T, T = blockdiag over the nodes of the node rotation: P on the
!> translations and P again on the rotations (DIS_TR: DRX, DRY, DRZ turn as a vector);
!> in 2D the 2x2 rotation on (DX, DY), DRZ unchanged. DOF order node by node: DIS_TR
!> (DX, DY, DZ, DRX, DRY, DRZ), 2D_DIS_TR (DX, DY, DRZ).
module element_discrete
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    implicit none
    private

    public :: nautical_rotation, segment_rotation, segment_rotation_2d
    public :: dis_t_seg2_stiffness, dis_t_poi1_stiffness
    public :: dis_2d_t_seg2_stiffness, dis_2d_t_poi1_stiffness
    public :: spring_internal_forces
    public :: discrete_local_matrix, discrete_rotate_to_global, plane_rotation

contains

    !> Rotation matrix of Code_Aster's nautical angles (alpha about Z, then beta about the
    !> new y, then gamma about the new x). Rows are the local axes in global components.
    !>  angles : in, (alpha, beta, gamma) in radians
    !>  pgl    : out, 3x3 orthogonal matrix, u_local = pgl u_global
    pure subroutine nautical_rotation(angles, pgl)
        real(dp), intent(in) :: angles(3)
        real(dp), intent(out) :: pgl(3, 3)
        real(dp) :: ca, sa, cb, sb, cg, sg
        ca = cos(angles(1)); sa = sin(angles(1))
        cb = cos(angles(2)); sb = sin(angles(2))
        cg = cos(angles(3)); sg = sin(angles(3))
        pgl(1, :) = [cb * ca, cb * sa, -sb]
        pgl(2, :) = [sg * sb * ca - cg * sa, cg * ca + sg * sb * sa, sg * cb]
        pgl(3, :) = [sg * sa + cg * sb * ca, cg * sb * sa - ca * sg, cg * cb]
    end subroutine nautical_rotation

    !> Local frame of a 3D segment (local x = node 1 -> node 2, roll angle ANGL_VRIL).
    !>  x1, x2    : in, node coordinates (3)
    !>  angl_vril : in, rotation about the local x in radians
    !>  pgl       : out, 3x3 rotation (rows = local axes)
    !>  st        : out, STATUS_MODEL_ERROR for a zero-length segment
    subroutine segment_rotation(x1, x2, angl_vril, pgl, st)
        real(dp), intent(in) :: x1(3), x2(3), angl_vril
        real(dp), intent(out) :: pgl(3, 3)
        type(status_t), intent(out) :: st
        real(dp) :: v(3), length, horiz, alpha, beta
        v = x2 - x1
        length = norm2(v)
        pgl = 0.0_dp
        if (.not. length > 0.0_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'SEG2 discrete of zero length has no ' // &
                'local frame (use REPERE=''GLOBAL'' or separate its nodes)')
            return
        end if
        horiz = hypot(v(1), v(2))
        ! Code_Aster angvx: a vertical segment gets alpha = 0.
        alpha = 0.0_dp
        if (horiz > epsilon(1.0_dp) * length) alpha = atan2(v(2), v(1))
        beta = -atan2(v(3), horiz)
        call nautical_rotation([alpha, beta, angl_vril], pgl)
    end subroutine segment_rotation

    !> Local frame of a 2D segment: rows (cos a, sin a) and (-sin a, cos a), a = direction.
    !>  x1, x2 : in, node coordinates (2); r : out, 2x2 rotation; st : out, zero length
    subroutine segment_rotation_2d(x1, x2, r, st)
        real(dp), intent(in) :: x1(2), x2(2)
        real(dp), intent(out) :: r(2, 2)
        type(status_t), intent(out) :: st
        real(dp) :: v(2), length
        v = x2 - x1
        length = norm2(v)
        r = 0.0_dp
        if (.not. length > 0.0_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'SEG2 discrete of zero length has no ' // &
                'local frame (use REPERE=''GLOBAL'' or separate its nodes)')
            return
        end if
        v = v / length
        r(1, :) = [v(1), v(2)]
        r(2, :) = [-v(2), v(1)]
    end subroutine segment_rotation_2d

    !> DIS_T on SEG2, K_T_D_L: 6x6 global stiffness.
    !>  coords       : in, coords(1:3, 2) node coordinates
    !>  kvals        : in, (kx, ky, kz) in the local frame, or global when global_frame
    !>  global_frame : in, .true. for REPERE = 'GLOBAL'
    !>  angl_vril    : in, roll angle about the local x (radians), ignored when global
    !>  ke           : out, [[K, -K], [-K, K]], K = P^T diag(k) P
    !>  st           : out, zero-length segment in the local frame
    subroutine dis_t_seg2_stiffness(coords, kvals, global_frame, angl_vril, ke, st)
        real(dp), intent(in) :: coords(3, 2), kvals(3), angl_vril
        logical, intent(in) :: global_frame
        real(dp), intent(out) :: ke(6, 6)
        type(status_t), intent(out) :: st
        real(dp) :: pgl(3, 3), k(3, 3)
        ke = 0.0_dp
        if (global_frame) then
            k = diagonal3(kvals)
        else
            call segment_rotation(coords(:, 1), coords(:, 2), angl_vril, pgl, st)
            if (st%failed()) return
            k = matmul(transpose(pgl), matmul(diagonal3(kvals), pgl))
        end if
        ke(1:3, 1:3) = k
        ke(4:6, 4:6) = k
        ke(1:3, 4:6) = -k
        ke(4:6, 1:3) = -k
    end subroutine dis_t_seg2_stiffness

    !> DIS_T on POI1, K_T_D_N: 3x3 global stiffness (a spring to the ground).
    !>  kvals        : in, (kx, ky, kz) in the local (or global) frame
    !>  global_frame : in, .true. for REPERE = 'GLOBAL'
    !>  angles       : in, nautical angles of ORIENTATION (radians); zeros = global axes
    !>  ke           : out, P^T diag(k) P
    pure subroutine dis_t_poi1_stiffness(kvals, global_frame, angles, ke)
        real(dp), intent(in) :: kvals(3), angles(3)
        logical, intent(in) :: global_frame
        real(dp), intent(out) :: ke(3, 3)
        real(dp) :: pgl(3, 3)
        if (global_frame) then
            ke = diagonal3(kvals)
        else
            call nautical_rotation(angles, pgl)
            ke = matmul(transpose(pgl), matmul(diagonal3(kvals), pgl))
        end if
    end subroutine dis_t_poi1_stiffness

    !> 2D_DIS_T on SEG2, K_T_D_L: 4x4 global stiffness.
    !>  coords : in, coords(1:2, 2); kvals : in, (kx, ky); global_frame : in, REPERE
    !>  ke     : out, [[K, -K], [-K, K]], K = R^T diag(k) R; st : out, zero length
    subroutine dis_2d_t_seg2_stiffness(coords, kvals, global_frame, ke, st)
        real(dp), intent(in) :: coords(2, 2), kvals(2)
        logical, intent(in) :: global_frame
        real(dp), intent(out) :: ke(4, 4)
        type(status_t), intent(out) :: st
        real(dp) :: r(2, 2), k(2, 2)
        ke = 0.0_dp
        k = 0.0_dp
        k(1, 1) = kvals(1)
        k(2, 2) = kvals(2)
        if (.not. global_frame) then
            call segment_rotation_2d(coords(:, 1), coords(:, 2), r, st)
            if (st%failed()) return
            k = matmul(transpose(r), matmul(k, r))
        end if
        ke(1:2, 1:2) = k
        ke(3:4, 3:4) = k
        ke(1:2, 3:4) = -k
        ke(3:4, 1:2) = -k
    end subroutine dis_2d_t_seg2_stiffness

    !> 2D_DIS_T on POI1, K_T_D_N: 2x2 global stiffness.
    !>  kvals : in, (kx, ky); global_frame : in; angle : in, ORIENTATION angle about z
    !>  ke    : out, R^T diag(k) R
    pure subroutine dis_2d_t_poi1_stiffness(kvals, global_frame, angle, ke)
        real(dp), intent(in) :: kvals(2), angle
        logical, intent(in) :: global_frame
        real(dp), intent(out) :: ke(2, 2)
        real(dp) :: r(2, 2)
        ke = 0.0_dp
        ke(1, 1) = kvals(1)
        ke(2, 2) = kvals(2)
        if (global_frame) return
        r(1, :) = [cos(angle), sin(angle)]
        r(2, :) = [-sin(angle), cos(angle)]
        ke = matmul(transpose(r), matmul(ke, r))
    end subroutine dis_2d_t_poi1_stiffness

    !> Internal forces of a linear spring: fe = ke ue.
    !>  ke : in, square stiffness; ue : in, displacements; fe : out, forces (same size)
    pure subroutine spring_internal_forces(ke, ue, fe)
        real(dp), intent(in) :: ke(:, :), ue(:)
        real(dp), intent(out) :: fe(:)
        fe = matmul(ke, ue)
    end subroutine spring_internal_forces

    !> The element matrix of a diagonal characteristic in the discrete's frame: diag(k) on a
    !> node, [[K, -K], [-K, K]] with K = diag(k) on a link.
    !>  k       : in, k(node_dofs) the diagonal (K_T_D_*, K_TR_D_* values)
    !>  n_nodes : in, 1 (POI1) or 2 (SEG2)
    !>  kl      : out, kl(n_nodes node_dofs, n_nodes node_dofs)
    pure subroutine discrete_local_matrix(k, n_nodes, kl)
        real(dp), intent(in) :: k(:)
        integer(i4), intent(in) :: n_nodes
        real(dp), intent(out) :: kl(:, :)
        integer(i4) :: i, nd
        nd = size(k, kind=i4)
        kl = 0.0_dp
        do i = 1, nd
            kl(i, i) = k(i)
            if (n_nodes == 2) then
                kl(nd + i, nd + i) = k(i)
                kl(i, nd + i) = -k(i)
                kl(nd + i, i) = -k(i)
            end if
        end do
    end subroutine discrete_local_matrix

    !> K_global = T^T K_local T (module header).
    !>  kl        : in, kl(nd, nd), nd = n_nodes node_dofs, in the discrete's frame
    !>  n_nodes   : in, 1 or 2
    !>  node_dofs : in, 2 (2D_DIS_T), 3 (DIS_T or 2D_DIS_TR) or 6 (DIS_TR)
    !>  two_d     : in, a 2D discrete (r(1:2, 1:2) is its rotation)
    !>  r         : in, 3x3 rotation, rows = local axes (2D: in r(1:2, 1:2))
    !>  ke        : out, ke(nd, nd)
    pure subroutine discrete_rotate_to_global(kl, n_nodes, node_dofs, two_d, r, ke)
        real(dp), intent(in) :: kl(:, :), r(3, 3)
        integer(i4), intent(in) :: n_nodes, node_dofs
        logical, intent(in) :: two_d
        real(dp), intent(out) :: ke(:, :)
        real(dp) :: t(12, 12), tn(6, 6)
        integer(i4) :: nd, a
        nd = n_nodes * node_dofs
        tn = 0.0_dp
        if (two_d) then
            tn(1:2, 1:2) = r(1:2, 1:2)
            if (node_dofs == 3) tn(3, 3) = 1.0_dp
        else
            tn(1:3, 1:3) = r
            if (node_dofs == 6) tn(4:6, 4:6) = r
        end if
        t = 0.0_dp
        do a = 0, n_nodes - 1
            t(a * node_dofs + 1:(a + 1) * node_dofs, a * node_dofs + 1:(a + 1) * node_dofs) = &
                tn(1:node_dofs, 1:node_dofs)
        end do
        ke(1:nd, 1:nd) = matmul(transpose(t(1:nd, 1:nd)), matmul(kl(1:nd, 1:nd), t(1:nd, 1:nd)))
    end subroutine discrete_rotate_to_global

    !> The 2D rotation of angle a about Z as a 3x3 (rows = local axes; r(3,3) = 1).
    pure function plane_rotation(a) result(r)
        real(dp), intent(in) :: a
        real(dp) :: r(3, 3)
        r = 0.0_dp
        r(1, 1:2) = [cos(a), sin(a)]
        r(2, 1:2) = [-sin(a), cos(a)]
        r(3, 3) = 1.0_dp
    end function plane_rotation

    pure function diagonal3(k) result(d)
        real(dp), intent(in) :: k(3)
        real(dp) :: d(3, 3)
        integer(i4) :: i
        d = 0.0_dp
        do i = 1, 3
            d(i, i) = k(i)
        end do
    end function diagonal3

end module element_discrete
