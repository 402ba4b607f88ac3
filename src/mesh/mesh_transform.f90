!> The geometric transformations of MODI_MAILLAGE (U4.23.04), as Code_Aster applies them to
!> every node (tranma, chgref, rotama, symema, echell). A transformation given with 2
!> components (TRANSLATION=(dx, dy), POIN_1=(x, y), VECT_X=(a, b), AXE_1=(a, b)) works in
!> the (x, y) plane and leaves z as it is. DEFORME's ALEA is Code_Aster's modi_alea, with
!> its generator (ggubs, IMSL's GGUBS: x <- 16807 x mod (2^31 - 1), seed 24331), so a
!> perturbed mesh is the one Code_Aster makes, node for node.
module mesh_transform
    use kinds, only: dp, i4
    use mesh_geometry, only: DEGREE, cross
    implicit none
    private

    public :: translate, change_basis, rotate, reflect, scale, perturb

contains

    !> x <- x + d (d(3) = 0 in the plane).
    pure subroutine translate(coords, d)
        real(dp), intent(inout) :: coords(:, :)
        real(dp), intent(in) :: d(3)
        integer(i4) :: k
        do k = 1, size(coords, 2, kind=i4)
            coords(:, k) = coords(:, k) + d
        end do
    end subroutine translate

    !> MODI_BASE (chgref): the coordinates in the orthonormal basis of the unit vectors
    !> ex, ey (and ez = ex x ey); in the plane (`plane`) ey = (-ex_y, ex_x) and z is kept.
    pure subroutine change_basis(coords, ex, ey, plane)
        real(dp), intent(inout) :: coords(:, :)
        real(dp), intent(in) :: ex(3), ey(3)
        logical, intent(in) :: plane
        real(dp) :: ez(3), p(3), y2(3)
        integer(i4) :: k
        if (plane) then
            y2 = [-ex(2), ex(1), 0.0_dp]
            do k = 1, size(coords, 2, kind=i4)
                p = coords(:, k)
                coords(1, k) = ex(1) * p(1) + ex(2) * p(2)
                coords(2, k) = y2(1) * p(1) + y2(2) * p(2)
            end do
            return
        end if
        ez = cross(ex, ey)
        do k = 1, size(coords, 2, kind=i4)
            p = coords(:, k)
            coords(:, k) = [dot_product(ex, p), dot_product(ey, p), dot_product(ez, p)]
        end do
    end subroutine change_basis

    !> ROTATION (rotama): by `angle` degrees about the axis through `point` along the unit
    !> vector `axis` (right-hand sense), or in the plane about `point` (z axis) when `plane`.
    pure subroutine rotate(coords, point, axis, angle, plane)
        real(dp), intent(inout) :: coords(:, :)
        real(dp), intent(in) :: point(3), axis(3), angle
        logical, intent(in) :: plane
        real(dp) :: c, s, r(3), along
        integer(i4) :: k
        c = cos(angle * DEGREE)
        s = sin(angle * DEGREE)
        do k = 1, size(coords, 2, kind=i4)
            r = coords(:, k) - point
            if (plane) then
                coords(1, k) = point(1) + c * r(1) - s * r(2)
                coords(2, k) = point(2) + c * r(2) + s * r(1)
            else
                ! Rodrigues: r cos + (1 - cos)(r.a) a + sin a x r
                along = dot_product(r, axis)
                coords(:, k) = point + c * r + (1.0_dp - c) * along * axis + &
                               s * cross(axis, r)
            end if
        end do
    end subroutine rotate

    !> SYMETRIE (symema): the mirror image in the plane through `point` normal to the unit
    !> vector `normal` (in the plane: the line through `point` normal to it).
    pure subroutine reflect(coords, point, normal)
        real(dp), intent(inout) :: coords(:, :)
        real(dp), intent(in) :: point(3), normal(3)
        real(dp) :: d
        integer(i4) :: k
        do k = 1, size(coords, 2, kind=i4)
            d = dot_product(normal, coords(:, k) - point)
            coords(:, k) = coords(:, k) - 2.0_dp * d * normal
        end do
    end subroutine reflect

    !> ECHELLE (echell): every coordinate times `factor`.
    pure subroutine scale(coords, factor)
        real(dp), intent(inout) :: coords(:, :)
        real(dp), intent(in) :: factor
        coords = coords * factor
    end subroutine scale

    !> DEFORME=_F(ALEA=alea) (modi_alea): each coordinate moves by alea * r * (its extent
    !> over the mesh), r uniform in [-1, 1], drawn for x, y, z of node 1, then of node 2...
    !> (a coordinate of no extent, z of a plane mesh, stays).
    pure subroutine perturb(coords, alea)
        real(dp), intent(inout) :: coords(:, :)
        real(dp), intent(in) :: alea
        real(dp), parameter :: D2P31M = 2147483647.0_dp, D2P31 = 2147483648.0_dp
        real(dp) :: extent(3), seed, r
        integer(i4) :: k, j
        if (size(coords, 2) == 0) return
        extent = alea * (maxval(coords, dim=2) - minval(coords, dim=2))
        seed = 24331.0_dp
        do k = 1, size(coords, 2, kind=i4)
            do j = 1, 3
                seed = 16807.0_dp * seed - aint(16807.0_dp * seed / D2P31M) * D2P31M
                r = seed / D2P31
                coords(j, k) = coords(j, k) + 2.0_dp * (r - 0.5_dp) * extent(j)
            end do
        end do
    end subroutine perturb

end module mesh_transform
