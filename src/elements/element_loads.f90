!> Load integration on plate cells (FORCE_COQUE: PRES, FX/FY/FZ) and on 2D edges
!> (FORCE_CONTOUR: FX, FY per unit length, unit depth).
!>
!> Two steps so the caller can evaluate load functions (formulas of X, Y, Z, INST) at the
!> integration points: (1) *_load_points gives the points in global space and their weights
!> (rule weight times the Jacobian, i.e. area or length measure); (2) *_forces turns the
!> values at those points into equivalent nodal forces f_i = sum_g N_i(g) q_g w_g with the
!> element's own linear (TRIA3, SEG2) / bilinear (QUAD4) interpolation N_i.
!> Rules: QUAD4 3x3 Gauss (N_i q J has degree <= 5 per direction for q quadratic on any
!> bilinear cell: exact); TRIA3 6-point degree-4 rule (N_i q of degree 3: exact); SEG2
!> 2-point Gauss (N_i q of degree 3: exact). Pressure: force = -PRES n, n the element
!> normal of element_plate (right-hand rule on the node order), so a positive pressure
!> pushes against n. Only translations receive forces: fe = (FX1, FY1, FZ1, FX2, ...).
module element_loads
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use element_quadrature, only: gauss_quad, dunavant_tria6, gauss_line
    use element_plane_quad4, only: quad4_shape
    use element_plate, only: plate_local_frame
    implicit none
    private

    !> Largest number of load points of a plate cell (QUAD4: 9, TRIA3: 6) and of an edge.
    integer(i4), parameter, public :: PLATE_LOAD_MAX_POINTS = 9
    integer(i4), parameter, public :: EDGE_POINT_COUNT = 2

    public :: plate_load_point_count, plate_load_points, plate_pressure_forces
    public :: plate_surface_forces, edge_load_points, edge_line_forces

contains

    !> Number of load points of a plate cell: 9 for QUAD4 (nn = 4), 6 for TRIA3 (nn = 3).
    pure integer(i4) function plate_load_point_count(nn)
        integer(i4), intent(in) :: nn
        plate_load_point_count = merge(9_i4, 6_i4, nn == 4)
    end function plate_load_point_count

    !> Load points of a plate cell.
    !>  coords : in, coords(1:3, nn) global node coordinates; nn : in, 3 or 4
    !>  xg     : out, xg(1:3, npt) global coordinates of the points (npt =
    !>           plate_load_point_count(nn); size >= npt)
    !>  wg     : out, wg(npt) weight times the area Jacobian |dx/dxi x dx/deta|
    !>  st     : out, STATUS_MODEL_ERROR for a degenerate cell
    subroutine plate_load_points(coords, nn, xg, wg, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: coords(3, nn)
        real(dp), intent(out) :: xg(:, :), wg(:)
        type(status_t), intent(out) :: st
        real(dp) :: n(4, PLATE_LOAD_MAX_POINTS)
        call plate_rule(coords, nn, xg, wg, n, st)
    end subroutine plate_load_points

    !> Nodal forces of a pressure on a plate cell: f_i = -n sum_g N_i(g) p_g w_g.
    !>  coords, nn : in, as plate_load_points
    !>  pres       : in, pres(npt) pressure values at the points of plate_load_points
    !>  fe         : out, fe(3nn) forces on (DX, DY, DZ) node by node, global frame
    !>  st         : out, degenerate cell
    subroutine plate_pressure_forces(coords, nn, pres, fe, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: coords(3, nn), pres(:)
        real(dp), intent(out) :: fe(3 * nn)
        type(status_t), intent(out) :: st
        real(dp) :: xg(3, PLATE_LOAD_MAX_POINTS), wg(PLATE_LOAD_MAX_POINTS)
        real(dp) :: n(4, PLATE_LOAD_MAX_POINTS), rot(3, 3), xy(2, nn), s
        integer(i4) :: i, npt
        fe = 0.0_dp
        call plate_local_frame(coords, nn, rot, xy, st)
        if (st%failed()) return
        call plate_rule(coords, nn, xg, wg, n, st)
        if (st%failed()) return
        npt = plate_load_point_count(nn)
        do i = 1, nn
            s = sum(n(i, 1:npt) * pres(1:npt) * wg(1:npt))
            fe(3 * i - 2:3 * i) = -s * rot(3, :)
        end do
    end subroutine plate_pressure_forces

    !> Nodal forces of a surface force (FORCE_COQUE FX, FY, FZ, global components).
    !>  coords, nn : in, as plate_load_points
    !>  fsurf      : in, fsurf(1:3, npt) force per unit area at the points
    !>  fe         : out, fe(3nn); st : out, degenerate cell
    subroutine plate_surface_forces(coords, nn, fsurf, fe, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: coords(3, nn), fsurf(:, :)
        real(dp), intent(out) :: fe(3 * nn)
        type(status_t), intent(out) :: st
        real(dp) :: xg(3, PLATE_LOAD_MAX_POINTS), wg(PLATE_LOAD_MAX_POINTS)
        real(dp) :: n(4, PLATE_LOAD_MAX_POINTS)
        integer(i4) :: i, g
        fe = 0.0_dp
        call plate_rule(coords, nn, xg, wg, n, st)
        if (st%failed()) return
        do i = 1, nn
            do g = 1, plate_load_point_count(nn)
                fe(3 * i - 2:3 * i) = fe(3 * i - 2:3 * i) + n(i, g) * wg(g) * fsurf(1:3, g)
            end do
        end do
    end subroutine plate_surface_forces

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

    !> Points, weights (times |J|) and shape-function values n(i, g) of a plate cell.
    subroutine plate_rule(coords, nn, xg, wg, n, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: coords(3, nn)
        real(dp), intent(out) :: xg(:, :), wg(:), n(4, PLATE_LOAD_MAX_POINTS)
        type(status_t), intent(out) :: st
        real(dp) :: xi(2, PLATE_LOAD_MAX_POINTS), w(PLATE_LOAD_MAX_POINTS), dn(2, 4), t(3, 2)
        real(dp) :: area
        integer(i4) :: g, npt
        n = 0.0_dp
        npt = plate_load_point_count(nn)
        if (nn == 4) then
            call gauss_quad(3_i4, xi, w)
        else
            call dunavant_tria6(xi, w)
        end if
        do g = 1, npt
            if (nn == 4) then
                call quad4_shape(xi(1, g), xi(2, g), n(1:4, g), dn)
            else
                n(1:3, g) = [1.0_dp - xi(1, g) - xi(2, g), xi(1, g), xi(2, g)]
                dn(:, 1) = [-1.0_dp, -1.0_dp]
                dn(:, 2) = [1.0_dp, 0.0_dp]
                dn(:, 3) = [0.0_dp, 1.0_dp]
            end if
            xg(1:3, g) = matmul(coords, n(1:nn, g))
            t = matmul(coords, transpose(dn(:, 1:nn)))
            area = norm2([t(2, 1) * t(3, 2) - t(3, 1) * t(2, 2), &
                          t(3, 1) * t(1, 2) - t(1, 1) * t(3, 2), &
                          t(1, 1) * t(2, 2) - t(2, 1) * t(1, 2)])
            if (.not. area > 0.0_dp) then
                call set_error(st, STATUS_MODEL_ERROR, 'plate cell with a zero-area ' // &
                    'point: cannot integrate the load (degenerate cell)')
                return
            end if
            wg(g) = w(g) * area
        end do
    end subroutine plate_rule

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
