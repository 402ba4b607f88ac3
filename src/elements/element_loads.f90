!> Load integration on plate cells (FORCE_COQUE: PRES, FX/FY/FZ; PRES_REP: PRES) and on 2D
!> edges (FORCE_CONTOUR: FX, FY per unit length, unit depth).
!>
!> Plates, as Code_Aster's DKT/DKQ elements (te0032, options CHAR_MECA_FRCO3D / FFCO3D /
!> PRES_R; routines dxtfor, dxqfor): the load is known by its values q_j at the cell's NODES
!> (a function is evaluated there, a constant is the same at every node) and turned into
!> nodal forces f_i = sum_j W_ij q_j, componentwise:
!>   TRIA3 (DKT): lumped, W = diag(A/3);
!>   QUAD4 (DKQ): the cell is cut into its 4 corner triangles T_k = (k-1, k, k+1), which
!>     cover it twice; on each, the consistent weights of the linear triangle
!>     (A_k/6 on the diagonal, A_k/12 off it) are summed and halved.
!> A_k are the areas in the cell's local plane (element_plate's frame). For a field linear
!> over the cell both give its exact resultant; the DKQ weights also give its exact first
!> moments. A pressure acts against the element normal n (right-hand rule on the node
!> order): q_j = -PRES_j n. SSNL130 model A (P = 5 (y - 2)^2 at the nodes of the 4 x 16
!> grid): resultant 855/64 N, where the exact integral of P is 40/3 N (ssnl130.md).
!> Edges: the load is evaluated at the 2 Gauss points of the SEG2 and integrated with the
!> linear shape functions, f_i = sum_g N_i(g) q_g w_g (exact for q quadratic), as Code_Aster
!> integrates FORCE_CONTOUR on plane elements.
!> Only translations receive forces: fe = (FX1, FY1, FZ1, FX2, ...) in global components.
module element_loads
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use element_quadrature, only: gauss_line
    use element_plate, only: plate_local_frame
    implicit none
    private

    !> Number of Gauss points of an edge (FORCE_CONTOUR).
    integer(i4), parameter, public :: EDGE_POINT_COUNT = 2

    public :: plate_load_weights, plate_nodal_forces, plate_nodal_pressure
    public :: edge_load_points, edge_line_forces

contains

    !> Weights W(i, j) of a plate cell (see the module header): f_i = sum_j W(i, j) q_j.
    !>  coords : in, coords(1:3, nn) global node coordinates; nn : in, 3 or 4
    !>  w      : out, w(nn, nn) (symmetric; its entries sum to the cell's area)
    !>  normal : out, the unit normal n of the cell's local frame
    !>  st     : out, STATUS_MODEL_ERROR for a degenerate cell (zero area: no frame)
    subroutine plate_load_weights(coords, nn, w, normal, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: coords(3, nn)
        real(dp), intent(out) :: w(nn, nn), normal(3)
        type(status_t), intent(out) :: st
        real(dp) :: rot(3, 3), xy(2, nn), area
        integer(i4) :: k, km, kp, corner(3), i, j
        w = 0.0_dp
        normal = 0.0_dp
        call plate_local_frame(coords, nn, rot, xy, st)
        if (st%failed()) return
        normal = rot(3, :)
        if (nn == 3) then
            area = triangle_area(xy(:, 1), xy(:, 2), xy(:, 3))
            do k = 1, 3
                w(k, k) = area / 3.0_dp
            end do
            return
        end if
        do k = 1, 4
            km = modulo(k - 2, 4) + 1
            kp = modulo(k, 4) + 1
            corner = [km, k, kp]
            area = triangle_area(xy(:, km), xy(:, k), xy(:, kp))
            do j = 1, 3
                do i = 1, 3
                    w(corner(i), corner(j)) = w(corner(i), corner(j)) + 0.5_dp * area * &
                        merge(1.0_dp / 6.0_dp, 1.0_dp / 12.0_dp, i == j)
                end do
            end do
        end do
    end subroutine plate_load_weights

    !> Nodal forces of a surface force known at the nodes (FORCE_COQUE FX, FY, FZ).
    !>  coords, nn : in, as plate_load_weights
    !>  q          : in, q(1:3, nn) force per unit area at each node, global components
    !>  fe         : out, fe(3nn) forces on (DX, DY, DZ) node by node
    !>  st         : out, degenerate cell
    subroutine plate_nodal_forces(coords, nn, q, fe, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: coords(3, nn), q(3, nn)
        real(dp), intent(out) :: fe(3 * nn)
        type(status_t), intent(out) :: st
        real(dp) :: w(nn, nn), normal(3)
        integer(i4) :: i, j
        fe = 0.0_dp
        call plate_load_weights(coords, nn, w, normal, st)
        if (st%failed()) return
        do i = 1, nn
            do j = 1, nn
                fe(3 * i - 2:3 * i) = fe(3 * i - 2:3 * i) + w(i, j) * q(:, j)
            end do
        end do
    end subroutine plate_nodal_forces

    !> Nodal forces of a pressure known at the nodes (FORCE_COQUE / PRES_REP PRES):
    !> q_j = -PRES_j n.
    !>  pres : in, pres(nn) pressure at each node; other arguments as plate_nodal_forces
    subroutine plate_nodal_pressure(coords, nn, pres, fe, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: coords(3, nn), pres(nn)
        real(dp), intent(out) :: fe(3 * nn)
        type(status_t), intent(out) :: st
        real(dp) :: w(nn, nn), normal(3), s
        integer(i4) :: i
        fe = 0.0_dp
        call plate_load_weights(coords, nn, w, normal, st)
        if (st%failed()) return
        do i = 1, nn
            s = sum(w(i, :) * pres)
            fe(3 * i - 2:3 * i) = -s * normal
        end do
    end subroutine plate_nodal_pressure

    !> Signed area of the triangle (a, b, c) in the plane (positive counter-clockwise).
    pure real(dp) function triangle_area(a, b, c)
        real(dp), intent(in) :: a(2), b(2), c(2)
        triangle_area = 0.5_dp * ((b(1) - a(1)) * (c(2) - a(2)) - (b(2) - a(2)) * (c(1) - a(1)))
    end function triangle_area

    !> Load points of a 2D edge (SEG2), 2-point Gauss.
    !>  coords : in, coords(1:2, 2); xg : out, xg(1:2, 2); wg : out, wg(2) = weight * L/2
    !>  st     : out, STATUS_MODEL_ERROR for a zero-length edge
    subroutine edge_load_points(coords, xg, wg, st)
        real(dp), intent(in) :: coords(2, 2)
        real(dp), intent(out) :: xg(2, EDGE_POINT_COUNT), wg(EDGE_POINT_COUNT)
        type(status_t), intent(out) :: st
        real(dp) :: n(2, EDGE_POINT_COUNT)
        call edge_rule(coords, xg, wg, n, st)
    end subroutine edge_load_points

    !> Nodal forces of a line load (FORCE_CONTOUR FX, FY per unit length, unit depth).
    !>  coords : in, coords(1:2, 2); fline : in, fline(1:2, 2) load at the edge points
    !>  fe     : out, fe(4) = (FX1, FY1, FX2, FY2); st : out, zero-length edge
    subroutine edge_line_forces(coords, fline, fe, st)
        real(dp), intent(in) :: coords(2, 2), fline(2, EDGE_POINT_COUNT)
        real(dp), intent(out) :: fe(4)
        type(status_t), intent(out) :: st
        real(dp) :: xg(2, EDGE_POINT_COUNT), wg(EDGE_POINT_COUNT), n(2, EDGE_POINT_COUNT)
        integer(i4) :: i
        fe = 0.0_dp
        call edge_rule(coords, xg, wg, n, st)
        if (st%failed()) return
        do i = 1, 2
            fe(2 * i - 1) = sum(n(i, :) * wg * fline(1, :))
            fe(2 * i) = sum(n(i, :) * wg * fline(2, :))
        end do
    end subroutine edge_line_forces

    !> Points, weights (times L/2) and shape-function values of a 2D edge.
    subroutine edge_rule(coords, xg, wg, n, st)
        real(dp), intent(in) :: coords(2, 2)
        real(dp), intent(out) :: xg(2, EDGE_POINT_COUNT), wg(EDGE_POINT_COUNT)
        real(dp), intent(out) :: n(2, EDGE_POINT_COUNT)
        type(status_t), intent(out) :: st
        real(dp) :: xi(EDGE_POINT_COUNT), w(EDGE_POINT_COUNT), length
        integer(i4) :: g
        xg = 0.0_dp
        wg = 0.0_dp
        n = 0.0_dp
        length = norm2(coords(:, 2) - coords(:, 1))
        if (.not. length > 0.0_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'FORCE_CONTOUR on a zero-length edge')
            return
        end if
        call gauss_line(2_i4, xi, w)
        do g = 1, EDGE_POINT_COUNT
            n(:, g) = [0.5_dp * (1.0_dp - xi(g)), 0.5_dp * (1.0_dp + xi(g))]
            xg(:, g) = matmul(coords, n(:, g))
            wg(g) = w(g) * 0.5_dp * length
        end do
    end subroutine edge_rule

end module element_loads
