!> DIS_CHOC: unilateral (shock) law of discrete springs, without friction (see
!> /doc/elements.md and the SSNL130 physics notes).
!>
!> SEG2 (DIS_T 3D or 2D_DIS_T 2D), e = unit vector node 1 -> node 2 in the initial geometry:
!>   gap d = (x2 - x1 + u2 - u1) . e - (DIST_1 + DIST_2)
!> POI1, e = the local x axis of the discrete (an obstacle at distance JEU ahead of the node
!> along +e; the node closes the gap by moving along +e):
!>   gap d = JEU - DIST_1 - u . e
!> Closed iff d <= 0, where the round-off margin of one machine epsilon toward "closed"
!> applies to the initial gap d0 (the geometry): |d0| <= eps * L is taken as 0 (L = |x2 - x1|
!> for a SEG2, JEU + DIST_1 for a POI1), so a spring with L = DIST_1 starts just closed. The
!> displacement part is not subject to the margin: it is exact relative to itself, so an
!> opening of 1e-20 m is seen as open, and the status is homogeneous in the load down to the
!> smallest loads (doc/stability.md).
!> Closed: normal force FN = k_n d (negative = compression), k_n = RIGI_NOR if given, else
!> e^T K e (the discrete's own stiffness along e); tangential stiffness
!> K_t = P K P + RIGI_TAN P with P = I - e e^T (the discrete's stiffness across e; the
!> normal/tangential cross terms of a K not aligned with e are dropped). Relative
!> displacement r = u2 - u1 (SEG2) or -u (POI1); force on node 2: FN e + K_t r; matrix
!> block K_c = k_n e e^T + K_t. Open: no force and a zero matrix in every direction.
!> elastic = .true. (NEWTON PREDICTION/MATRICE = 'ELASTIQUE'): the returned matrix is the
!> closed (bilateral) one whatever the status; status, gap, FN and forces stay those of the
!> unilateral law (they make the residual).
!> COULOMB /= 0 (friction) is not built: the model layer refuses it.
module element_dis_choc
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    implicit none
    private

    public :: dis_choc_seg2, dis_choc_2d_seg2, dis_choc_poi1, dis_choc_2d_poi1, &
        dis_choc_seg2_gap

    !> Largest space dimension (size of the work arrays of the law).
    integer(i4), parameter :: MAX_DIM = 3

contains

    !> DIS_CHOC on a DIS_T SEG2.
    !>  coords : in, coords(1:3, 2) initial node coordinates
    !>  ue     : in, ue(6) displacements (DX1, DY1, DZ1, DX2, DY2, DZ2)
    !>  kdisc  : in, kdisc(3,3) the discrete's own stiffness block K (global frame), e.g.
    !>           ke(1:3,1:3) from dis_t_seg2_stiffness
    !>  dist1, dist2 : in, DIS_CONTACT DIST_1, DIST_2
    !>  elastic: in, .true. for the elastic (all closed, bilateral) matrix
    !>  closed : out, status; gap : out, d; fn : out, normal force (<= 0 when closed)
    !>  fe     : out, fe(6) internal forces; ke : out, ke(6,6) tangent matrix
    !>  st     : out, STATUS_MODEL_ERROR for a zero-length segment (no normal)
    !>  rigi_nor, rigi_tan : in, optional DIS_CONTACT RIGI_NOR / RIGI_TAN
    subroutine dis_choc_seg2(coords, ue, kdisc, dist1, dist2, elastic, closed, gap, fn, fe, &
                             ke, st, rigi_nor, rigi_tan)
        real(dp), intent(in) :: coords(3, 2), ue(6), kdisc(3, 3), dist1, dist2
        logical, intent(in) :: elastic
        logical, intent(out) :: closed
        real(dp), intent(out) :: gap, fn, fe(6), ke(6, 6)
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: rigi_nor, rigi_tan
        call choc_segment(3_i4, coords, ue, kdisc, dist1, dist2, elastic, closed, gap, fn, &
            fe, ke, st, rigi_nor, rigi_tan)
    end subroutine dis_choc_seg2

    !> DIS_CHOC on a 2D_DIS_T SEG2: as dis_choc_seg2 with coords(1:2, 2), ue(4)
    !> (DX1, DY1, DX2, DY2), kdisc(2,2), fe(4), ke(4,4).
    subroutine dis_choc_2d_seg2(coords, ue, kdisc, dist1, dist2, elastic, closed, gap, fn, &
                                fe, ke, st, rigi_nor, rigi_tan)
        real(dp), intent(in) :: coords(2, 2), ue(4), kdisc(2, 2), dist1, dist2
        logical, intent(in) :: elastic
        logical, intent(out) :: closed
        real(dp), intent(out) :: gap, fn, fe(4), ke(4, 4)
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: rigi_nor, rigi_tan
        call choc_segment(2_i4, coords, ue, kdisc, dist1, dist2, elastic, closed, gap, fn, &
            fe, ke, st, rigi_nor, rigi_tan)
    end subroutine dis_choc_2d_seg2

    !> DIS_CHOC on a DIS_T POI1 (node against a fixed obstacle).
    !>  ue    : in, ue(3) node displacement; ex : in, ex(3) local x axis (global components,
    !>          need not be normalised), e.g. row 1 of nautical_rotation
    !>  kdisc : in, kdisc(3,3) the discrete's stiffness (K_T_D_N, global frame)
    !>  jeu, dist1 : in, DIS_CONTACT JEU and DIST_1
    !>  elastic, closed, gap, fn : as dis_choc_seg2; fe : out, fe(3); ke : out, ke(3,3)
    !>  st    : out, STATUS_MODEL_ERROR if ex is zero
    subroutine dis_choc_poi1(ue, ex, kdisc, jeu, dist1, elastic, closed, gap, fn, fe, ke, &
                             st, rigi_nor, rigi_tan)
        real(dp), intent(in) :: ue(3), ex(3), kdisc(3, 3), jeu, dist1
        logical, intent(in) :: elastic
        logical, intent(out) :: closed
        real(dp), intent(out) :: gap, fn, fe(3), ke(3, 3)
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: rigi_nor, rigi_tan
        call choc_point(3_i4, ue, ex, kdisc, jeu, dist1, elastic, closed, gap, fn, fe, ke, &
            st, rigi_nor, rigi_tan)
    end subroutine dis_choc_poi1

    !> DIS_CHOC on a 2D_DIS_T POI1: as dis_choc_poi1 with ue(2), ex(2), kdisc(2,2), fe(2),
    !> ke(2,2).
    subroutine dis_choc_2d_poi1(ue, ex, kdisc, jeu, dist1, elastic, closed, gap, fn, fe, ke, &
                                st, rigi_nor, rigi_tan)
        real(dp), intent(in) :: ue(2), ex(2), kdisc(2, 2), jeu, dist1
        logical, intent(in) :: elastic
        logical, intent(out) :: closed
        real(dp), intent(out) :: gap, fn, fe(2), ke(2, 2)
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: rigi_nor, rigi_tan
        call choc_point(2_i4, ue, ex, kdisc, jeu, dist1, elastic, closed, gap, fn, fe, ke, &
            st, rigi_nor, rigi_tan)
    end subroutine dis_choc_2d_poi1

    !> SEG2 in n dimensions (n = 2 or 3).
    subroutine choc_segment(n, coords, ue, kdisc, dist1, dist2, elastic, closed, gap, fn, &
                            fe, ke, st, rigi_nor, rigi_tan)
        integer(i4), intent(in) :: n
        real(dp), intent(in) :: coords(n, 2), ue(2 * n), kdisc(n, n), dist1, dist2
        logical, intent(in) :: elastic
        logical, intent(out) :: closed
        real(dp), intent(out) :: gap, fn, fe(2 * n), ke(2 * n, 2 * n)
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: rigi_nor, rigi_tan
        real(dp) :: e(MAX_DIM), r(MAX_DIM), length, f2(MAX_DIM)
        real(dp) :: kc(n, n)    ! contiguous for choc_law (a 2x2 section of 3x3 is not)
        fe = 0.0_dp
        ke = 0.0_dp
        closed = .false.
        gap = 0.0_dp
        fn = 0.0_dp
        e(1:n) = coords(:, 2) - coords(:, 1)
        length = norm2(e(1:n))
        if (.not. length > 0.0_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'DIS_CHOC on a SEG2 of zero length: ' // &
                'no contact normal (the two nodes must be distinct)')
            return
        end if
        e(1:n) = e(1:n) / length
        r(1:n) = ue(n + 1:2 * n) - ue(1:n)
        call choc_law(n, e(1:n), r(1:n), length - (dist1 + dist2), length, &
            kdisc, elastic, closed, gap, fn, f2(1:n), kc, rigi_nor, rigi_tan)
        fe(1:n) = -f2(1:n)
        fe(n + 1:2 * n) = f2(1:n)
        ke(1:n, 1:n) = kc
        ke(n + 1:2 * n, n + 1:2 * n) = kc
        ke(1:n, n + 1:2 * n) = -kc
        ke(n + 1:2 * n, 1:n) = -kc
    end subroutine choc_segment

    !> POI1 in n dimensions: node 1 of a virtual SEG2 whose node 2 is the fixed obstacle.
    subroutine choc_point(n, ue, ex, kdisc, jeu, dist1, elastic, closed, gap, fn, fe, ke, &
                          st, rigi_nor, rigi_tan)
        integer(i4), intent(in) :: n
        real(dp), intent(in) :: ue(n), ex(n), kdisc(n, n), jeu, dist1
        logical, intent(in) :: elastic
        logical, intent(out) :: closed
        real(dp), intent(out) :: gap, fn, fe(n), ke(n, n)
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: rigi_nor, rigi_tan
        real(dp) :: e(MAX_DIM), f2(MAX_DIM), r(MAX_DIM)
        fe = 0.0_dp
        ke = 0.0_dp
        closed = .false.
        gap = 0.0_dp
        fn = 0.0_dp
        if (.not. norm2(ex) > 0.0_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'DIS_CHOC on a POI1: the local x axis ' // &
                '(contact normal) is zero')
            return
        end if
        e(1:n) = ex / norm2(ex)
        r(1:n) = -ue
        call choc_law(n, e(1:n), r(1:n), jeu - dist1, abs(jeu) + abs(dist1), kdisc, elastic, &
            closed, gap, fn, f2(1:n), ke, rigi_nor, rigi_tan)
        fe = -f2(1:n)
    end subroutine choc_point

    !> The law itself. d = d0 + r . e, with |d0| <= eps * scale taken as 0; closed iff d <= 0.
    !>  f2 : out, force on the "node 2" side (FN e + K_t r when closed)
    !>  kc : out, K_c = k_n e e^T + K_t when closed or elastic, else 0
    !> Explicit loops on fixed-size work arrays (n <= MAX_DIM): no heap temporaries in this
    !> per-spring, per-iteration kernel; the sums run in the order of the matmul/dot_product
    !> expressions they replace (ascending index), so the results are unchanged.
    pure subroutine choc_law(n, e, r, d0, scale, kdisc, elastic, closed, gap, fn, f2, kc, &
                             rigi_nor, rigi_tan)
        integer(i4), intent(in) :: n
        real(dp), intent(in) :: e(n), r(n), d0, scale, kdisc(n, n)
        logical, intent(in) :: elastic
        logical, intent(out) :: closed
        real(dp), intent(out) :: gap, fn, f2(n), kc(n, n)
        real(dp), intent(in), optional :: rigi_nor, rigi_tan
        real(dp) :: p(MAX_DIM, MAX_DIM), kt(MAX_DIM, MAX_DIM), w(MAX_DIM, MAX_DIM), kn, t
        integer(i4) :: i, j, k
        do j = 1, n
            do i = 1, n
                p(i, j) = -e(i) * e(j)
            end do
            p(j, j) = p(j, j) + 1.0_dp
        end do
        kn = 0.0_dp
        do i = 1, n
            t = 0.0_dp
            do k = 1, n
                t = t + kdisc(i, k) * e(k)
            end do
            kn = kn + e(i) * t
        end do
        if (present(rigi_nor)) kn = rigi_nor
        call small_matmul(n, kdisc, p, w)
        call small_matmul(n, p, w, kt)
        if (present(rigi_tan)) kt(1:n, 1:n) = kt(1:n, 1:n) + rigi_tan * p(1:n, 1:n)
        t = 0.0_dp
        do i = 1, n
            t = t + r(i) * e(i)
        end do
        gap = contact_gap(d0, scale, t)
        closed = gap <= 0.0_dp
        fn = 0.0_dp
        f2 = 0.0_dp
        kc = 0.0_dp
        if (closed .or. elastic) then
            do j = 1, n
                do i = 1, n
                    kc(i, j) = kn * e(i) * e(j) + kt(i, j)
                end do
            end do
        end if
        if (.not. closed) return
        fn = kn * gap
        do i = 1, n
            t = 0.0_dp
            do k = 1, n
                t = t + kt(i, k) * r(k)
            end do
            f2(i) = fn * e(i) + t
        end do
    end subroutine choc_law

    !> The gap d = d0 + t of the law (module header): an initial gap |d0| <= eps * scale is
    !> taken as 0; the normal motion t is exact relative to itself.
    pure real(dp) function contact_gap(d0, scale, t) result(gap)
        real(dp), intent(in) :: d0, scale, t
        if (abs(d0) <= epsilon(1.0_dp) * scale) then
            gap = t
        else
            gap = d0 + t
        end if
    end function contact_gap

    !> The normal gap d of a SEG2 spring at displacements ue (as dis_choc_seg2 computes it;
    !> the V1 internal variable of element_spring_fields).
    !>  n      : in, 3 (DIS_T) or 2 (2D_DIS_T)
    !>  coords : in, coords(1:n, 2) node coordinates;  ue : in, ue(2n) displacements
    !>  dist1, dist2 : in, DIS_CONTACT DIST_1, DIST_2
    !>  gap    : out, d (0 for a zero-length segment, which dis_choc_seg2 refuses)
    pure subroutine dis_choc_seg2_gap(n, coords, ue, dist1, dist2, gap)
        integer(i4), intent(in) :: n
        real(dp), intent(in) :: coords(n, 2), ue(2 * n), dist1, dist2
        real(dp), intent(out) :: gap
        real(dp) :: e(MAX_DIM), length, t
        integer(i4) :: i
        gap = 0.0_dp
        e(1:n) = coords(:, 2) - coords(:, 1)
        length = norm2(e(1:n))
        if (.not. length > 0.0_dp) return
        e(1:n) = e(1:n) / length              ! the same operations as choc_segment
        t = 0.0_dp
        do i = 1, n
            t = t + (ue(n + i) - ue(i)) * e(i)
        end do
        gap = contact_gap(length - (dist1 + dist2), length, t)
    end subroutine dis_choc_seg2_gap

    !> c(1:n, 1:n) = a b for n x n matrices (n <= MAX_DIM), sums in ascending order.
    pure subroutine small_matmul(n, a, b, c)
        integer(i4), intent(in) :: n
        real(dp), intent(in) :: a(:, :), b(:, :)
        real(dp), intent(out) :: c(MAX_DIM, MAX_DIM)
        integer(i4) :: i, j, k
        c = 0.0_dp
        do j = 1, n
            do i = 1, n
                do k = 1, n
                    c(i, j) = c(i, j) + a(i, k) * b(k, j)
                end do
            end do
        end do
    end subroutine small_matmul

end module element_dis_choc
