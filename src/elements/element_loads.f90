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
!> Edges (SEG2, SEG3 of D_PLAN / C_PLAN models): the load is evaluated at the points of
!> Code_Aster's RIGI family of the skin element (MEPLSE2: FPG2, MEPLSE3: FPG4;
!> element_gauss_families) and integrated with the edge's shape functions,
!> f_i = sum_g N_i(g) q_g |dx/dxi| w_g (exact for q quadratic on a straight SEG2, for q of
!> degree 5 on a straight SEG3), as Code_Aster integrates FORCE_CONTOUR and PRES_REP on
!> plane elements. The edge normal is Code_Aster's (vff2dn): n = (dy/ds, -dx/ds), the
!> tangent node 1 -> node 2 turned clockwise (outward for a skin that turns
!> counter-clockwise around its solid); a pressure p gives the traction -p n.
!> Plane solid cells (FORCE_INTERNE, PESANTEUR): the force per unit area is known at the
!> points of the cell's RIGI family and integrated with its shape functions (te0093,
!> te0094, te0085), exact for a constant force (the cell's area to round-off).
!> Plates receive forces and moments (FORCE_COQUE MX..MZ, MF1, MF2) with the same weights.
module element_loads
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use element_plate, only: plate_local_frame
    use mesh_cell_shapes, only: CELL_SEG2, CELL_SEG3, CELL_TYPE_NODES, CELL_TYPE_NAMES, &
        MAX_CELL_NODES, cell_shape
    use element_gauss_families, only: gauss_rule_t, gauss_family, FORMULATION_PLANE_EDGE, &
        MAX_GAUSS_POINTS
    use element_plane, only: plane_rigi_rule, plane_derivatives, check_plane_jacobians
    implicit none
    private

    !> Most points and nodes of a plane edge (SEG3: FPG4, 3 nodes).
    integer(i4), parameter, public :: MAX_EDGE_POINTS = 4, MAX_EDGE_NODES = 3

    !> The load points of one plane edge (edge_load_points).
    type, public :: edge_points_t
        integer(i4) :: n = 0                                !< points
        integer(i4) :: nn = 0                               !< nodes of the edge (2 or 3)
        real(dp) :: x(2, MAX_EDGE_POINTS) = 0.0_dp          !< positions
        real(dp) :: w(MAX_EDGE_POINTS) = 0.0_dp             !< weight times |dx/dxi|
        real(dp) :: shape(MAX_EDGE_NODES, MAX_EDGE_POINTS) = 0.0_dp  !< N_i at the points
        real(dp) :: normal(2, MAX_EDGE_POINTS) = 0.0_dp     !< unit normal (module header)
    end type edge_points_t

    !> The load points of one plane solid cell (plane_load_points).
    type, public :: area_points_t
        integer(i4) :: n = 0                                    !< points
        integer(i4) :: nn = 0                                   !< nodes of the cell
        real(dp) :: x(2, MAX_GAUSS_POINTS) = 0.0_dp             !< positions
        real(dp) :: w(MAX_GAUSS_POINTS) = 0.0_dp                !< weight times |det J|
        real(dp) :: shape(MAX_CELL_NODES, MAX_GAUSS_POINTS) = 0.0_dp   !< N_i at the points
    end type area_points_t

    public :: plate_load_weights, plate_nodal_forces, plate_nodal_pressure, plate_nodal_values
    public :: edge_load_points, edge_line_forces, plane_load_points, area_forces

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

    !> Nodal forces and moments of surface forces and moments known at the nodes
    !> (FORCE_COQUE FX..MZ, F1..MF2 turned to global components; PESANTEUR): the weights of
    !> plate_load_weights on each of the six components, as Code_Aster's dxtfor / dxqfor
    !> apply them to the six components in the cell's frame (a rotation commutes with them).
    !>  q  : in, q(1:6, nn) force and moment per unit area at each node, global components
    !>  fe : out, fe(1:6, nn) on (DX, DY, DZ, DRX, DRY, DRZ) node by node
    subroutine plate_nodal_values(coords, nn, q, fe, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: coords(3, nn), q(6, nn)
        real(dp), intent(out) :: fe(6, nn)
        type(status_t), intent(out) :: st
        real(dp) :: w(nn, nn), normal(3)
        integer(i4) :: i, j
        fe = 0.0_dp
        call plate_load_weights(coords, nn, w, normal, st)
        if (st%failed()) return
        do i = 1, nn
            do j = 1, nn
                fe(:, i) = fe(:, i) + w(i, j) * q(:, j)
            end do
        end do
    end subroutine plate_nodal_values

    !> Load points of a plane solid cell (FORCE_INTERNE, PESANTEUR): the points of its RIGI
    !> family with the weights w_g |det J|, as Code_Aster's te0093 / te0094 / te0085
    !> integrate f_i = sum_g N_i(g) q_g |det J| w_g (unit depth).
    !>  ctype : in, a plane surface type (TRIA3 .. QUAD9)
    !>  xy    : in, xy(2, nn) node coordinates
    !>  st    : out, STATUS_MODEL_ERROR for a degenerate cell (element_plane)
    subroutine plane_load_points(ctype, xy, pts, st)
        integer(i4), intent(in) :: ctype
        real(dp), intent(in) :: xy(:, :)
        type(area_points_t), intent(out) :: pts
        type(status_t), intent(out) :: st
        type(gauss_rule_t) :: rule
        real(dp) :: dxy(2, MAX_CELL_NODES), det(MAX_GAUSS_POINTS)
        integer(i4) :: g, nn
        call plane_rigi_rule(ctype, rule, st)
        if (st%failed()) return
        nn = CELL_TYPE_NODES(ctype)
        pts%n = rule%n
        pts%nn = nn
        do g = 1, rule%n
            call plane_derivatives(ctype, xy, rule%xi(1, g), rule%xi(2, g), &
                pts%shape(1:nn, g), dxy, det(g))
            pts%x(:, g) = matmul(xy(1:2, 1:nn), pts%shape(1:nn, g))
            pts%w(g) = rule%w(g) * abs(det(g))
        end do
        call check_plane_jacobians(ctype, xy, det(1:rule%n), st)
    end subroutine plane_load_points

    !> Nodal forces of a force per unit area (unit depth) known at the load points:
    !> f_i = sum_g N_i(g) q_g w_g.
    !>  q  : in, q(1:2, pts%n) (FX, FY) at the points
    !>  fe : out, fe(1:2 pts%nn) = (FX1, FY1, FX2, ...)
    pure subroutine area_forces(pts, q, fe)
        type(area_points_t), intent(in) :: pts
        real(dp), intent(in) :: q(:, :)
        real(dp), intent(out) :: fe(:)
        call point_forces(pts%shape, pts%w, q, pts%n, pts%nn, fe)
    end subroutine area_forces

    ! f_i = sum_g N_i(g) q_g w_g for (FX, FY) known at n points, nn nodes.
    pure subroutine point_forces(shape, w, q, n, nn, fe)
        real(dp), intent(in) :: shape(:, :), w(:), q(:, :)
        integer(i4), intent(in) :: n, nn
        real(dp), intent(out) :: fe(:)
        integer(i4) :: i
        fe = 0.0_dp
        do i = 1, nn
            fe(2 * i - 1) = sum(shape(i, 1:n) * w(1:n) * q(1, 1:n))
            fe(2 * i) = sum(shape(i, 1:n) * w(1:n) * q(2, 1:n))
        end do
    end subroutine point_forces

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

    !> Load points of a plane edge: positions, weights, shape functions and normals at the
    !> points of the skin element's RIGI family (module header).
    !>  ctype  : in, CELL_SEG2 or CELL_SEG3
    !>  coords : in, coords(1:2, nn) node coordinates (SEG3: ends, then middle)
    !>  pts    : out
    !>  st     : out, STATUS_MODEL_ERROR for another cell type or an edge of zero length
    !>           (|dx/dxi| zero at a point, relative to the edge's size)
    subroutine edge_load_points(ctype, coords, pts, st)
        integer(i4), intent(in) :: ctype
        real(dp), intent(in) :: coords(:, :)
        type(edge_points_t), intent(out) :: pts
        type(status_t), intent(out) :: st
        type(gauss_rule_t) :: rule
        real(dp) :: dn(2, MAX_EDGE_NODES), t(2), jac, size
        integer(i4) :: g, nn
        if (ctype /= CELL_SEG2 .and. ctype /= CELL_SEG3) then
            call set_error(st, STATUS_MODEL_ERROR, 'an edge load needs a SEG2 or SEG3 ' // &
                'edge, not a ' // trim(CELL_TYPE_NAMES(ctype)))
            return
        end if
        call gauss_family(FORMULATION_PLANE_EDGE, ctype, 'RIGI', rule, st)
        if (st%failed()) return
        nn = CELL_TYPE_NODES(ctype)
        pts%n = rule%n
        pts%nn = nn
        size = norm2(coords(1:2, 2) - coords(1:2, 1))
        if (nn == 3) size = max(size, norm2(coords(1:2, 3) - coords(1:2, 1)), &
                                norm2(coords(1:2, 3) - coords(1:2, 2)))
        do g = 1, rule%n
            call cell_shape(ctype, rule%xi(1, g), 0.0_dp, pts%shape(1:nn, g), dn(:, 1:nn))
            pts%x(:, g) = matmul(coords(1:2, 1:nn), pts%shape(1:nn, g))
            t = matmul(coords(1:2, 1:nn), dn(1, 1:nn))
            jac = norm2(t)
            if (.not. (size > 0.0_dp .and. jac > 1.0e3_dp * epsilon(1.0_dp) * size)) then
                call set_error(st, STATUS_MODEL_ERROR, 'zero-length edge (its ' // &
                    trim(CELL_TYPE_NAMES(ctype)) // ' nodes coincide or fold back)')
                return
            end if
            pts%w(g) = rule%w(g) * jac
            pts%normal(:, g) = [t(2), -t(1)] / jac
        end do
    end subroutine edge_load_points

    !> Nodal forces of a line load (per unit length, unit depth) known at the load points:
    !> f_i = sum_g N_i(g) q_g w_g.
    !>  pts   : in, edge_load_points
    !>  fline : in, fline(1:2, pts%n) the load (FX, FY) at the points
    !>  fe    : out, fe(1:2 pts%nn) = (FX1, FY1, FX2, FY2[, FX3, FY3])
    pure subroutine edge_line_forces(pts, fline, fe)
        type(edge_points_t), intent(in) :: pts
        real(dp), intent(in) :: fline(:, :)
        real(dp), intent(out) :: fe(:)
        call point_forces(pts%shape, pts%w, fline, pts%n, pts%nn, fe)
    end subroutine edge_line_forces

end module element_loads
