!> Where a point of space falls in a mesh: the cell holding it and its reference
!> coordinates there, so that a field can be interpolated with the cell's shape functions
!> (Code_Aster's PROJ_CHAMP METHODE='COLLOCATION', which MACR_LIGN_COUPE uses, U4.72.05).
!> Lines and surfaces (SEG2/3, TRIA3/6, QUAD4/8/9) are located in three-dimensional space:
!> the reference coordinates minimise the distance from the point to the cell's image
!> (Gauss-Newton on the isoparametric map, whose residual vanishes for a point of the
!> cell), then are brought back into the reference element; the distance is that of the
!> point to the image of the clamped coordinates. A point on a side shared by two cells
!> goes to the first of them in the mesh's order.
!> Written for MACR_LIGN_COUPE (issue 20) while `field` builds PROJ_CHAMP; once its point
!> location lands, the two should become one.
module point_location
    use kinds, only: dp, i4
    use mesh_types, only: mesh_t
    use mesh_cell_shapes, only: cell_shape, CELL_TYPE_DIM, CELL_TYPE_NODES, MAX_CELL_NODES, &
        CELL_TRIA3, CELL_TRIA6, CELL_SEG2, CELL_SEG3
    implicit none
    private

    !> A located point: its cell (0 when none holds it), reference coordinates, the shape
    !> functions there and the distance from the point to the cell.
    type, public :: located_point_t
        integer(i4) :: cell = 0
        real(dp) :: xi(2) = 0.0_dp
        real(dp) :: shape(MAX_CELL_NODES) = 0.0_dp
        real(dp) :: distance = huge(1.0_dp)
    end type located_point_t

    !> Relative size (to a cell's diameter) under which a point counts as on the cell, and
    !> two distances as equal: rounding of the coordinates, not geometry.
    real(dp), parameter :: ON_CELL = 1.0e-9_dp
    !> Gauss-Newton iterations: the map is bilinear at most biquadratic, a few suffice.
    integer, parameter :: MAX_ITERATIONS = 30

    public :: locate_point, cell_diameter

contains

    !> The cell among `candidate` that holds point p, or the nearest one within
    !> distance_max (a cell's own rounding, ON_CELL times its diameter, always allowed).
    !>  mesh         : in, the mesh
    !>  candidate    : in, (n_cells) the cells the point may fall in
    !>  p            : in, the point
    !>  distance_max : in, >= 0
    !>  loc          : out, loc%cell = 0 when no candidate is near enough
    subroutine locate_point(mesh, candidate, p, distance_max, loc)
        type(mesh_t), intent(in) :: mesh
        logical, intent(in) :: candidate(:)
        real(dp), intent(in) :: p(3), distance_max
        type(located_point_t), intent(out) :: loc
        type(located_point_t) :: trial
        real(dp) :: box_lo(3), box_hi(3), h, slack
        integer(i4) :: c, a, b
        do c = 1, mesh%n_cells
            if (.not. candidate(c)) cycle
            a = mesh%cell_ptr(c)
            b = mesh%cell_ptr(c + 1) - 1
            box_lo = minval(mesh%coords(:, mesh%cell_nodes(a:b)), dim=2)
            box_hi = maxval(mesh%coords(:, mesh%cell_nodes(a:b)), dim=2)
            h = cell_diameter(mesh, c)
            slack = distance_max + ON_CELL * h
            if (any(p < box_lo - slack) .or. any(p > box_hi + slack)) cycle
            call nearest_in_cell(mesh, c, p, trial)
            if (trial%distance > slack) cycle
            if (loc%cell == 0 .or. trial%distance < loc%distance - ON_CELL * h) loc = trial
        end do
    end subroutine locate_point

    !> The largest distance between two nodes of cell c.
    pure real(dp) function cell_diameter(mesh, c) result(h)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c
        integer(i4) :: i, j
        h = 0.0_dp
        do i = mesh%cell_ptr(c), mesh%cell_ptr(c + 1) - 1
            do j = i + 1, mesh%cell_ptr(c + 1) - 1
                h = max(h, norm2(mesh%coords(:, mesh%cell_nodes(i)) - &
                                 mesh%coords(:, mesh%cell_nodes(j))))
            end do
        end do
    end function cell_diameter

    !> The point of cell c nearest to p (see the module header).
    subroutine nearest_in_cell(mesh, c, p, loc)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: p(3)
        type(located_point_t), intent(out) :: loc
        real(dp) :: x(3, MAX_CELL_NODES), n(MAX_CELL_NODES), dn(2, MAX_CELL_NODES)
        real(dp) :: jac(3, 2), r(3), g(2, 2), rhs(2), step(2), det, xi(2)
        integer(i4) :: ctype, nn, dim, it
        ctype = mesh%cell_type(c)
        nn = CELL_TYPE_NODES(ctype)
        dim = CELL_TYPE_DIM(ctype)
        loc%cell = c
        x(:, 1:nn) = mesh%coords(:, mesh%cell_nodes(mesh%cell_ptr(c):mesh%cell_ptr(c) + nn - 1))
        if (dim == 0) then
            loc%shape(1) = 1.0_dp
            loc%distance = norm2(p - x(:, 1))
            return
        end if
        xi = reference_centre(ctype)
        do it = 1, MAX_ITERATIONS
            call cell_shape(ctype, xi(1), xi(2), n, dn)
            r = p - matmul(x(:, 1:nn), n(1:nn))
            jac(:, 1) = matmul(x(:, 1:nn), dn(1, 1:nn))
            jac(:, 2) = matmul(x(:, 1:nn), dn(2, 1:nn))
            if (dim == 1) then
                det = dot_product(jac(:, 1), jac(:, 1))
                if (.not. det > 0.0_dp) exit
                step = [dot_product(jac(:, 1), r) / det, 0.0_dp]
            else
                g(1, 1) = dot_product(jac(:, 1), jac(:, 1))
                g(1, 2) = dot_product(jac(:, 1), jac(:, 2))
                g(2, 2) = dot_product(jac(:, 2), jac(:, 2))
                det = g(1, 1) * g(2, 2) - g(1, 2)**2
                if (.not. det > 0.0_dp) exit
                rhs = [dot_product(jac(:, 1), r), dot_product(jac(:, 2), r)]
                step = [g(2, 2) * rhs(1) - g(1, 2) * rhs(2), &
                        g(1, 1) * rhs(2) - g(1, 2) * rhs(1)] / det
            end if
            ! a far point must not send the iterate to infinity: stay near the element
            xi = max(-3.0_dp, min(3.0_dp, xi + step))
            if (maxval(abs(step)) < 1.0e-13_dp) exit
        end do
        call clamp_reference(ctype, xi)
        call cell_shape(ctype, xi(1), xi(2), n, dn)
        loc%xi = xi
        loc%shape(1:nn) = n(1:nn)
        loc%distance = norm2(p - matmul(x(:, 1:nn), n(1:nn)))
    end subroutine nearest_in_cell

    pure function reference_centre(ctype) result(xi)
        integer(i4), intent(in) :: ctype
        real(dp) :: xi(2)
        xi = 0.0_dp
        if (ctype == CELL_TRIA3 .or. ctype == CELL_TRIA6) xi = [1.0_dp, 1.0_dp] / 3.0_dp
    end function reference_centre

    !> Brings reference coordinates into the reference element (the segment [-1, 1], the
    !> triangle xi, eta >= 0, xi + eta <= 1, the square [-1, 1]^2).
    pure subroutine clamp_reference(ctype, xi)
        integer(i4), intent(in) :: ctype
        real(dp), intent(inout) :: xi(2)
        real(dp) :: excess
        select case (ctype)
        case (CELL_SEG2, CELL_SEG3)
            xi(1) = max(-1.0_dp, min(1.0_dp, xi(1)))
            xi(2) = 0.0_dp
        case (CELL_TRIA3, CELL_TRIA6)
            xi = max(0.0_dp, xi)
            excess = xi(1) + xi(2) - 1.0_dp
            if (excess > 0.0_dp) xi = max(0.0_dp, xi - excess / 2.0_dp)
            if (xi(1) + xi(2) > 1.0_dp) xi = xi / (xi(1) + xi(2))
        case default
            xi = max(-1.0_dp, min(1.0_dp, xi))
        end select
    end subroutine clamp_reference

end module point_location
