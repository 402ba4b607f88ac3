!> The frames of MACR_LIGN_COUPE's REPERE (U4.81.13), as Code_Aster's macro sets them up
!> (macr_lign_coupe_ops.crea_resu_local): it turns the result projected on the line's mesh
!> with MODI_REPERE (UTILISATEUR, CYLINDRIQUE, and LOCAL as nautical angles), or reads it
!> with POST_RELEVE_T REPERE='POLAIRE'. parasol turns the values at each point the same way:
!>  - segment_local_angles  LOCAL on a SEGMENT: x along the segment, y the part of VECT_Y
!>                          orthogonal to it (one frame for the line);
!>  - path_local_angles     LOCAL on a GROUP_NO: at each point x the sum of the vectors of
!>                          its (one or two) segments of the line, normalised; in 2D y = z x x,
!>                          in 3D z = x ^ VECT_Y, y = z ^ x. As the macro forms it, the
!>                          vectors of the segments have no z component (it subtracts the end
!>                          node's z from itself), so the tangent is that of the line's
!>                          projection on the xy plane;
!>  - cylinder_frame        CYLINDRIQUE: rows (e_r, e_z, e_theta) about the axis through
!>                          ORIGINE along AXE_Z (2D: z), a point on the axis taking the centre
!>                          of the first segment of the line around it, as MODI_REPERE takes
!>                          the centre of a cell;
!>  - turn_point            the components of a point in a frame, as MODI_REPERE turns them
!>                          (vectors DX DY DZ, DRX DRY DRZ, FLUX FLUY FLUZ: P v; tensors
!>                          SIXX .. SIYZ: P S P^T, in a 2D CYLINDRIQUE frame SIXY = r theta).
!> Angles are in degrees, as the macro passes them to MODI_REPERE (ANGL_NAUT).
module lign_coupe_frames
    use kinds, only: dp
    use strings, only: string_t
    use releve_frames, only: rotate_vector, rotate_tensor
    implicit none
    private

    public :: segment_local_angles, path_local_angles, cylinder_frame, turn_point

    !> Precision of Code_Aster's crea_resu_local (epsi): parallel axes, a vertical tangent.
    real(dp), parameter, public :: LOCAL_EPSILON = 1.0e-8_dp
    real(dp), parameter :: DEGREES_PER_RADIAN = 45.0_dp / atan(1.0_dp)

contains

    !> Nautical angles (degrees) of the frame x = cx (unit), y from vy (unit, not along
    !> cx), z = x ^ y, as crea_resu_local computes them (2D: alpha alone).
    pure function frame_angles(cx, vy, dim) result(angles)
        real(dp), intent(in) :: cx(3), vy(3)
        integer, intent(in) :: dim
        real(dp) :: angles(3), cy(3), cz(3)
        cz = cross(cx, vy)
        cz = cz / norm2(cz)
        cy = cross(cz, cx)
        angles = 0.0_dp
        if (dim == 2) then
            angles(1) = atan2(cx(2), cx(1))
        else if (cx(1)**2 + cx(2)**2 > LOCAL_EPSILON) then
            angles = [atan2(cx(2), cx(1)), -asin(max(-1.0_dp, min(1.0_dp, cx(3)))), &
                      atan2(cy(3), cz(3))]
        else
            angles = [atan2(-cy(1), cy(2)), -asin(max(-1.0_dp, min(1.0_dp, cx(3)))), 0.0_dp]
        end if
        angles = angles * DEGREES_PER_RADIAN
    end function frame_angles

    !> LOCAL on a SEGMENT from a to b: x along it, y the part of vect_y orthogonal to x.
    !>  ok : false when vect_y is along the segment (Code_Aster's POST0_3)
    pure subroutine segment_local_angles(a, b, vect_y, dim, angles, ok)
        real(dp), intent(in) :: a(3), b(3), vect_y(3)
        integer, intent(in) :: dim
        real(dp), intent(out) :: angles(3)
        logical, intent(out) :: ok
        real(dp) :: cx(3), cy(3)
        cx = b - a
        if (dim == 2) cx(3) = 0.0_dp
        cx = cx / norm2(cx)
        cy = vect_y / norm2(vect_y)
        angles = 0.0_dp
        ok = .not. (all(abs(cx - cy) < LOCAL_EPSILON) .or. all(abs(cx + cy) < LOCAL_EPSILON))
        if (ok) angles = frame_angles(cx, cy, dim)
    end subroutine segment_local_angles

    !> LOCAL on a GROUP_NO: the angles at each point of the path x (3, n) (module header).
    !>  bad : 0, or the first point where the tangent has no direction (two points at the same
    !>        place in xy) or, in 3D, where VECT_Y is along it
    pure subroutine path_local_angles(x, vect_y, dim, angles, bad)
        real(dp), intent(in) :: x(:, :), vect_y(3)
        integer, intent(in) :: dim
        real(dp), intent(out) :: angles(3, size(x, 2))
        integer, intent(out) :: bad
        real(dp) :: t(3), d(3), vy(3)
        integer :: i, n
        n = size(x, 2)
        angles = 0.0_dp
        bad = 0
        vy = [0.0_dp, 0.0_dp, 1.0_dp]
        if (dim == 3) vy = vect_y / norm2(vect_y)
        do i = 1, n
            t = 0.0_dp
            if (i > 1) then
                d = x(:, i) - x(:, i - 1)
                t = t + [d(1), d(2), 0.0_dp]
            end if
            if (i < n) then
                d = x(:, i + 1) - x(:, i)
                t = t + [d(1), d(2), 0.0_dp]
            end if
            if (.not. norm2(t) > 0.0_dp) then
                bad = i
                return
            end if
            t = t / norm2(t)
            if (dim == 3) then
                if (.not. norm2(cross(t, vy)) > LOCAL_EPSILON) then
                    bad = i
                    return
                end if
            end if
            angles(:, i) = frame_angles(t, vy, dim)
        end do
    end subroutine path_local_angles

    !> The cylindrical frame (rows e_r, e_z, e_theta) at point i of the line x (3, n) about
    !> the axis through `origin` along the unit `axis` (2D: z, the points' z ignored).
    !>  ok : false when the point and the centre of its first segment are on the axis
    pure subroutine cylinder_frame(x, i, origin, axis, dim, pgl, ok)
        real(dp), intent(in) :: x(:, :), origin(3), axis(3)
        integer, intent(in) :: i, dim
        real(dp), intent(out) :: pgl(3, 3)
        logical, intent(out) :: ok
        real(dp) :: er(3), scale
        integer :: j
        pgl = 0.0_dp
        scale = max(1.0_dp, maxval(abs(x)))
        er = radial(x(:, i))
        if (.not. norm2(er) > 1.0e-6_dp * scale .and. size(x, 2) > 1) then
            j = max(i, 2)                         ! the segment (j-1, j) comes first
            er = radial(0.5_dp * (x(:, j - 1) + x(:, j)))
        end if
        ok = norm2(er) > 1.0e-6_dp * scale
        if (.not. ok) return
        er = er / norm2(er)
        pgl(1, :) = er
        pgl(2, :) = axis
        pgl(3, :) = cross(axis, er)
        pgl(3, :) = pgl(3, :) / norm2(pgl(3, :))
    contains
        pure function radial(p) result(r)
            real(dp), intent(in) :: p(3)
            real(dp) :: r(3)
            r = p - origin
            if (dim == 2) r(3) = 0.0_dp
            r = r - dot_product(r, axis) * axis
        end function radial
    end subroutine cylinder_frame

    !> The components `names` of one point (values `v`, present where `has`) in the frame
    !> pgl (rows: the new axes), in place; a component of a group the point lacks counts 0.
    subroutine turn_point(names, v, has, pgl, cylindrical, dim)
        type(string_t), intent(in) :: names(:)
        real(dp), intent(inout) :: v(:)
        logical, intent(in) :: has(:), cylindrical
        real(dp), intent(in) :: pgl(3, 3)
        integer, intent(in) :: dim
        call turn_group([character(len=4) :: 'DX', 'DY', 'DZ'])
        call turn_group([character(len=4) :: 'DRX', 'DRY', 'DRZ'])
        call turn_group([character(len=4) :: 'FLUX', 'FLUY', 'FLUZ'])
        call turn_group([character(len=4) :: 'SIXX', 'SIYY', 'SIZZ', 'SIXY', 'SIXZ', 'SIYZ'])
    contains
        subroutine turn_group(group)
            character(len=4), intent(in) :: group(:)
            real(dp) :: g(size(group)), w(size(group))
            integer :: where(size(group)), k, j
            where = 0
            do k = 1, size(group)
                do j = 1, size(names)
                    if (names(j)%s == trim(group(k)) .and. has(j)) where(k) = j
                end do
            end do
            if (all(where == 0)) return
            g = 0.0_dp
            do k = 1, size(group)
                if (where(k) > 0) g(k) = v(where(k))
            end do
            if (size(group) == 3) then
                w = rotate_vector(pgl, g)
            else
                w = rotate_tensor(pgl, g)
                if (cylindrical .and. dim == 2) w(4) = w(5)     ! TENS_2D: SIXY = r theta
            end if
            do k = 1, size(group)
                if (where(k) > 0) v(where(k)) = w(k)
            end do
        end subroutine turn_group
    end subroutine turn_point

    pure function cross(a, b) result(c)
        real(dp), intent(in) :: a(3), b(3)
        real(dp) :: c(3)
        c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
    end function cross

end module lign_coupe_frames
