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
        dis_choc_line_seg2, dis_choc_seg2_gap
    ! shared with DIS_CONTACT (element_dis_contact): the same stiffness across the axis and
    ! the same two-node matrix
    public :: choc_stiffness, pair_matrix

    !> The spring's energy along a straight path u + alpha du (a line search):
    !>   E(alpha) = 0 when open, gap(alpha) = gap + alpha slope > 0, else
    !>   E(alpha) = kn/2 gap(alpha)^2 + t0 + alpha t1 + alpha^2 t2 / 2,
    !> the potential of the closed branch (normal force FN = kn gap, tangential K_t r):
    !> t0 = r^T K_t r / 2, t1 = r^T K_t dr, t2 = dr^T K_t dr for the relative displacement
    !> r (at u) and its change dr (along du); force = |kn gap e + K_t r|, the force the
    !> spring carries at u when closed. Lengths are divided by a scale s (gap, slope, r, dr),
    !> so energies come divided by s^2 and the force by s: free of overflow at any scale.
    type, public :: choc_line_t
        real(dp) :: kn = 0.0_dp, gap = 0.0_dp, slope = 0.0_dp
        real(dp) :: t0 = 0.0_dp, t1 = 0.0_dp, t2 = 0.0_dp
        real(dp) :: force = 0.0_dp
    end type choc_line_t

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
        call pair_matrix(n, kc, ke)
    end subroutine choc_segment

    !> The matrix of a spring between two nodes whose relative displacement r = u2 - u1 has
    !> the stiffness kc: [kc -kc; -kc kc].
    pure subroutine pair_matrix(n, kc, ke)
        integer(i4), intent(in) :: n
        real(dp), intent(in) :: kc(:, :)
        real(dp), intent(out) :: ke(2 * n, 2 * n)
        ke(1:n, 1:n) = kc(1:n, 1:n)
        ke(n + 1:2 * n, n + 1:2 * n) = kc(1:n, 1:n)
        ke(1:n, n + 1:2 * n) = -kc(1:n, 1:n)
        ke(n + 1:2 * n, 1:n) = -kc(1:n, 1:n)
    end subroutine pair_matrix

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
        real(dp) :: kt(MAX_DIM, MAX_DIM), kn, t
        integer(i4) :: i, j, k
        call choc_stiffness(n, e, kdisc, kn, kt, rigi_nor, rigi_tan)
        gap = choc_gap(n, e, r, d0, scale)
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

    !> Normal stiffness kn (RIGI_NOR, else e^T K e) and tangential K_t = P K P + RIGI_TAN P,
    !> P = I - e e^T, of a closed spring (module header).
    pure subroutine choc_stiffness(n, e, kdisc, kn, kt, rigi_nor, rigi_tan)
        integer(i4), intent(in) :: n
        real(dp), intent(in) :: e(n), kdisc(n, n)
        real(dp), intent(out) :: kn, kt(MAX_DIM, MAX_DIM)
        real(dp), intent(in), optional :: rigi_nor, rigi_tan
        real(dp) :: p(MAX_DIM, MAX_DIM), w(MAX_DIM, MAX_DIM), t
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
    end subroutine choc_stiffness

    !> Gap d = d0 + r . e, with |d0| <= eps * scale taken as 0 (module header).
    pure real(dp) function choc_gap(n, e, r, d0, scale) result(gap)
        integer(i4), intent(in) :: n
        real(dp), intent(in) :: e(n), r(n), d0, scale
        real(dp) :: t
        integer(i4) :: i
        t = 0.0_dp
        do i = 1, n
            t = t + r(i) * e(i)
        end do
        gap = contact_gap(d0, scale, t)
    end function choc_gap

    !> The energy of a DIS_CHOC SEG2 (2D or 3D) along u + alpha du (choc_line_t): the gap
    !> and the closed-branch coefficients, with the law's own gap, kn and K_t.
    !>  n      : in, 2 or 3 (space dimension)
    !>  coords : in, coords(1:n, 2) initial node coordinates
    !>  ue, de : in, (2n) element displacements at u and along du
    !>  kdisc, dist1, dist2, rigi_nor, rigi_tan : as dis_choc_seg2
    !>  scale  : in, > 0, the length scale s of the results (choc_line_t)
    !>  line   : out, zero (an inert spring) for a zero-length segment, which
    !>           dis_choc_seg2 refuses; the gap's sign is the law's (the gap is computed
    !>           as dis_choc_seg2 does, then divided by s)
    pure subroutine dis_choc_line_seg2(n, coords, ue, de, kdisc, dist1, dist2, scale, line, &
                                       rigi_nor, rigi_tan)
        integer(i4), intent(in) :: n
        real(dp), intent(in) :: coords(n, 2), ue(2 * n), de(2 * n), kdisc(n, n), dist1, dist2
        real(dp), intent(in) :: scale
        type(choc_line_t), intent(out) :: line
        real(dp), intent(in), optional :: rigi_nor, rigi_tan
        real(dp) :: e(MAX_DIM), r(MAX_DIM), dr(MAX_DIM), kt(MAX_DIM, MAX_DIM), length
        real(dp) :: ktr(MAX_DIM), ktdr(MAX_DIM)
        integer(i4) :: i, k
        e(1:n) = coords(:, 2) - coords(:, 1)
        length = norm2(e(1:n))
        if (.not. length > 0.0_dp) return
        e(1:n) = e(1:n) / length
        r(1:n) = ue(n + 1:2 * n) - ue(1:n)
        dr(1:n) = (de(n + 1:2 * n) - de(1:n)) / scale
        call choc_stiffness(n, e(1:n), kdisc, line%kn, kt, rigi_nor, rigi_tan)
        line%gap = choc_gap(n, e(1:n), r(1:n), length - (dist1 + dist2), length) / scale
        r(1:n) = r(1:n) / scale
        line%slope = dot_product(dr(1:n), e(1:n))
        do i = 1, n
            ktr(i) = 0.0_dp
            ktdr(i) = 0.0_dp
            do k = 1, n
                ktr(i) = ktr(i) + kt(i, k) * r(k)
                ktdr(i) = ktdr(i) + kt(i, k) * dr(k)
            end do
        end do
        line%t0 = 0.5_dp * dot_product(r(1:n), ktr(1:n))
        line%t1 = dot_product(r(1:n), ktdr(1:n))
        line%t2 = dot_product(dr(1:n), ktdr(1:n))
        line%force = norm2(line%kn * line%gap * e(1:n) + ktr(1:n))
    end subroutine dis_choc_line_seg2

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
