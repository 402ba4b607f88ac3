!> Geometric primitives of the mesh commands (DEFI_GROUP options, MODI_MAILLAGE): directions
!> from nautical angles, distances to points, axes and planes, normals of edges and faces,
!> the plane test of a mesh, points in cells. Pure functions on coordinates.
module mesh_geometry
    use kinds, only: dp, i4
    use mesh_types, only: mesh_t
    implicit none
    private

    !> Degrees to radians.
    real(dp), parameter, public :: DEGREE = 3.14159265358979323846264338327950288_dp / 180.0_dp

    public :: nautical_direction, normalized, axis_distance, z_constant, edge_normal_2d, &
        face_normal, cross, signed_area_2d, point_in_polygon_2d, point_in_triangle_3d

contains

    !> The unit direction of Code_Aster's nautical angles (degrees): in 2D (one angle a)
    !> (cos a, sin a, 0); in 3D (angles a, b) (cos a cos b, sin a cos b, -sin b).
    pure function nautical_direction(angles, ndim) result(v)
        real(dp), intent(in) :: angles(:)
        integer(i4), intent(in) :: ndim
        real(dp) :: v(3), a, b
        a = 0.0_dp
        b = 0.0_dp
        if (size(angles) >= 1) a = angles(1) * DEGREE
        if (size(angles) >= 2) b = angles(2) * DEGREE
        if (ndim == 2) then
            v = [cos(a), sin(a), 0.0_dp]
        else
            v = [cos(a) * cos(b), sin(a) * cos(b), -sin(b)]
        end if
    end function nautical_direction

    !> v / |v|; ok = false (and v returned as is) when |v| is 0. The norm is formed from the
    !> scaled vector, so components up to huge() do not overflow.
    pure subroutine normalized(v, u, ok)
        real(dp), intent(in) :: v(3)
        real(dp), intent(out) :: u(3)
        logical, intent(out) :: ok
        real(dp) :: scale
        u = v
        scale = maxval(abs(v))
        ok = scale > 0.0_dp
        if (.not. ok) return
        u = v / scale
        u = u / norm2(u)
    end subroutine normalized

    !> Distance of x from the line through x0 along the unit vector `axis`.
    pure real(dp) function axis_distance(x, x0, axis) result(d)
        real(dp), intent(in) :: x(3), x0(3), axis(3)
        real(dp) :: r(3)
        r = x - x0
        d = norm2(r - dot_product(r, axis) * axis)
    end function axis_distance

    !> True when every node of the mesh has the same z (Code_Aster's Z_CST): the geometric
    !> options then work in the (x, y) plane, z ignored.
    logical function z_constant(mesh)
        type(mesh_t), intent(in) :: mesh
        z_constant = .true.
        if (mesh%n_nodes == 0) return
        ! exact equality (spelled with < and >): Code_Aster compares the stored values
        z_constant = .not. any(mesh%coords(3, 1:mesh%n_nodes) < mesh%coords(3, 1) .or. &
                               mesh%coords(3, 1:mesh%n_nodes) > mesh%coords(3, 1))
    end function z_constant

    !> Unit normal (dy, -dx)/|.| of the segment x1 -> x2 in the (x, y) plane: to the right of
    !> the direction of travel, Code_Aster's convention for plane edges (canor2);
    !> ok = false for a segment of zero length in the plane.
    pure subroutine edge_normal_2d(x1, x2, n, ok)
        real(dp), intent(in) :: x1(3), x2(3)
        real(dp), intent(out) :: n(3)
        logical, intent(out) :: ok
        call normalized([x2(2) - x1(2), -(x2(1) - x1(1)), 0.0_dp], n, ok)
    end subroutine edge_normal_2d

    !> Unit normal (x2 - x1) x (x3 - x1) / |.| of the face through its first three nodes
    !> (Code_Aster's canor3); ok = false for three aligned points.
    pure subroutine face_normal(x1, x2, x3, n, ok)
        real(dp), intent(in) :: x1(3), x2(3), x3(3)
        real(dp), intent(out) :: n(3)
        logical, intent(out) :: ok
        call normalized(cross(x2 - x1, x3 - x1), n, ok)
    end subroutine face_normal

    pure function cross(a, b) result(c)
        real(dp), intent(in) :: a(3), b(3)
        real(dp) :: c(3)
        c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
    end function cross

    !> Signed area of the polygon x(:, 1..n) in the (x, y) plane (positive counterclockwise),
    !> by the shoelace formula on coordinates relative to the first point.
    pure real(dp) function signed_area_2d(x) result(a)
        real(dp), intent(in) :: x(:, :)
        integer :: i, j, n
        real(dp) :: p(2), q(2)
        n = size(x, 2)
        a = 0.0_dp
        do i = 2, n - 1
            j = i + 1
            p = x(1:2, i) - x(1:2, 1)
            q = x(1:2, j) - x(1:2, 1)
            a = a + p(1) * q(2) - p(2) * q(1)
        end do
        a = 0.5_dp * a
    end function signed_area_2d

    !> True when point p lies inside or on the boundary of the polygon x(:, 1..n) (convex or
    !> not, either orientation) in the (x, y) plane, within `tolerance` (a length).
    pure logical function point_in_polygon_2d(p, x, tolerance) result(inside)
        real(dp), intent(in) :: p(3), x(:, :), tolerance
        integer :: i, j, n
        real(dp) :: a(2), b(2), t, d
        logical :: crossing
        n = size(x, 2)
        ! on an edge (within tolerance): inside
        do i = 1, n
            j = mod(i, n) + 1
            a = x(1:2, i)
            b = x(1:2, j)
            t = dot_product(p(1:2) - a, b - a)
            d = dot_product(b - a, b - a)
            if (d > 0.0_dp) then
                t = max(0.0_dp, min(1.0_dp, t / d))
            else
                t = 0.0_dp
            end if
            if (norm2(p(1:2) - (a + t * (b - a))) <= tolerance) then
                inside = .true.
                return
            end if
        end do
        ! even-odd rule on a ray towards +x
        crossing = .false.
        do i = 1, n
            j = mod(i, n) + 1
            a = x(1:2, i)
            b = x(1:2, j)
            if ((a(2) > p(2)) .neqv. (b(2) > p(2))) then
                t = a(1) + (p(2) - a(2)) * (b(1) - a(1)) / (b(2) - a(2))
                if (p(1) < t) crossing = .not. crossing
            end if
        end do
        inside = crossing
    end function point_in_polygon_2d

    !> True when point p is within `tolerance` of the triangle x1 x2 x3 in space (its
    !> projection inside the triangle and its distance to the plane at most tolerance).
    pure logical function point_in_triangle_3d(p, x1, x2, x3, tolerance) result(inside)
        real(dp), intent(in) :: p(3), x1(3), x2(3), x3(3), tolerance
        real(dp) :: n(3), e1(3), e2(3), r(3), d11, d12, d22, dr1, dr2, det, u, v, h, area
        logical :: ok
        inside = .false.
        call face_normal(x1, x2, x3, n, ok)
        if (.not. ok) return
        h = dot_product(p - x1, n)
        if (abs(h) > tolerance) return
        e1 = x2 - x1
        e2 = x3 - x1
        r = p - h * n - x1
        d11 = dot_product(e1, e1)
        d12 = dot_product(e1, e2)
        d22 = dot_product(e2, e2)
        dr1 = dot_product(r, e1)
        dr2 = dot_product(r, e2)
        det = d11 * d22 - d12 * d12
        u = (d22 * dr1 - d12 * dr2) / det
        v = (d11 * dr2 - d12 * dr1) / det
        ! barycentric tolerance: `tolerance` over the triangle's size
        area = sqrt(det)
        h = tolerance * sqrt(max(d11, d22)) / area
        inside = u >= -h .and. v >= -h .and. u + v <= 1.0_dp + h
    end function point_in_triangle_3d

end module mesh_geometry
