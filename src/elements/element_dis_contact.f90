!> DIS_CONTACT: the incremental contact law of discrete SEG2 springs (COMPORTEMENT
!> RELATION = 'DIS_CONTACT'), static and frictionless (COULOMB = 0), as Code_Aster
!> integrates it (bibfor/elements/dis_contact_frot.F90 with ldc_dis_contact_frot.F90; the
!> DIS_CONTACT law documentation, R5.03.17).
!>
!> Local axis e = unit vector node 1 -> node 2 of the initial geometry, relative displacement
!> r = u2 - u1, normal part U = r . e, gap offset jeu = L - DIST_1 - DIST_2 (L = |x2 - x1|):
!> the spring is in contact when U + jeu <= 0. Code_Aster integrates the normal force over the
!> step as an ODE along the straight path from U- (start of the step) to U (no velocity in
!> statics): dF = k_n dU while in contact with F < 0, dF = 0 otherwise (out of contact, or
!> in contact without compression), and F = 0 at the end when out of contact. With the
!> force F- and displacement U- of the start of the step this gives in closed form
!>     F = min(0, F- + k_n (U - U-))   if U + jeu <= 0 and F- < 0,   F = 0 otherwise.
!> Before its first step a spring has U- = 0 and F- = k_n jeu if jeu <= 0 ("initial
!> contact"), F- = 0 otherwise. Consequences Code_Aster has too: a spring carries a force
!> only if it starts in contact, which is why SSNL130 C/D set DIST_1 = L + 1e-9 (every
!> spring starts 1e-9 m pressed, F- = -k_n 1e-9); with DIST_1 = L exactly the springs never
!> carry anything; and a spring that ends a step open (F = 0) never pushes again.
!> The tangential stiffness is the discrete's own across e, K_t = P K P (P = I - e e^T),
!> always active, in contact or not: tangential force K_t r (COULOMB = 0: no friction
!> threshold, so RIGI_TAN plays no part). Normal stiffness k_n = RIGI_NOR if given, else
!> e^T K e (the discrete's own along e).
!> Tangent: k_n,t e e^T + K_t with k_n,t = |F - F-| / |U - U-| in contact when the normal
!> increment exceeds the machine epsilon (k_n on a loading path, 0 for a spring stuck at
!> F = 0), k_n when it does not (the prediction at the start of a step), 0 out of contact.
!> Elastic matrix (MATRICE / PREDICTION = 'ELASTIQUE': Code_Aster's option RIGI_MECA) =
!> the discrete's own matrix K, whatever the contact state; forces stay the law's.
module element_dis_contact
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use element_dis_choc, only: choc_stiffness, pair_matrix
    implicit none
    private

    public :: dis_contact_seg2, dis_contact_start

    !> Largest space dimension (size of the work arrays of the law).
    integer(i4), parameter :: MAX_DIM = 3

contains

    !> State of a spring before its first step: the normal displacement U- = 0 and the
    !> force F- = k_n jeu when jeu = L - DIST_1 - DIST_2 <= 0 ("initial contact"), else 0.
    !>  n      : in, space dimension (2 or 3)
    !>  coords : in, coords(1:n, 2) node coordinates
    !>  kdisc  : in, kdisc(n, n) the discrete's stiffness block (global frame)
    !>  dist1, dist2 : in, DIS_CONTACT DIST_1, DIST_2
    !>  fn0, un0 : out, F- and U-
    !>  st     : out, STATUS_MODEL_ERROR for a zero-length segment
    !>  rigi_nor : in, optional, DIS_CONTACT RIGI_NOR
    subroutine dis_contact_start(n, coords, kdisc, dist1, dist2, fn0, un0, st, rigi_nor)
        integer(i4), intent(in) :: n
        real(dp), intent(in) :: coords(n, 2), kdisc(n, n), dist1, dist2
        real(dp), intent(out) :: fn0, un0
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: rigi_nor
        real(dp) :: e(MAX_DIM), length, kn, jeu, kt(MAX_DIM, MAX_DIM)
        fn0 = 0.0_dp
        un0 = 0.0_dp
        call axis(n, coords, e, length, st)
        if (st%failed()) return
        call choc_stiffness(n, e(1:n), kdisc, kn, kt, rigi_nor)
        jeu = length - (dist1 + dist2)
        if (jeu <= 0.0_dp) fn0 = kn * jeu
    end subroutine dis_contact_start

    !> DIS_CONTACT on a DIS_T (n = 3) or 2D_DIS_T (n = 2) SEG2.
    !>  n      : in, 2 or 3
    !>  coords : in, coords(1:n, 2) initial node coordinates
    !>  ue     : in, ue(2n) displacements at the end of the step (node 1, then node 2)
    !>  kdisc  : in, kdisc(n, n) the discrete's own stiffness block K (global frame)
    !>  dist1, dist2 : in, DIS_CONTACT DIST_1, DIST_2
    !>  fn0, un0 : in, normal force and normal displacement at the start of the step
    !>  elastic: in, .true. for the elastic matrix (the discrete's K)
    !>  closed : out, in contact at the end of the step (U + jeu <= 0)
    !>  fn     : out, normal force F (<= 0); un : out, normal displacement U
    !>  fe     : out, fe(2n) internal forces; ke : out, ke(2n, 2n) tangent (or elastic) matrix
    !>  st     : out, STATUS_MODEL_ERROR for a zero-length segment (no axis)
    !>  rigi_nor : in, optional, DIS_CONTACT RIGI_NOR
    subroutine dis_contact_seg2(n, coords, ue, kdisc, dist1, dist2, fn0, un0, elastic, closed, &
                                fn, un, fe, ke, st, rigi_nor)
        integer(i4), intent(in) :: n
        real(dp), intent(in) :: coords(n, 2), ue(2 * n), kdisc(n, n), dist1, dist2, fn0, un0
        logical, intent(in) :: elastic
        logical, intent(out) :: closed
        real(dp), intent(out) :: fn, un, fe(2 * n), ke(2 * n, 2 * n)
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: rigi_nor
        real(dp) :: e(MAX_DIM), r(MAX_DIM), f2(MAX_DIM), kt(MAX_DIM, MAX_DIM)
        real(dp) :: kc(MAX_DIM, MAX_DIM), length, kn, ktan_n, du
        integer(i4) :: i, j
        fe = 0.0_dp
        ke = 0.0_dp
        closed = .false.
        fn = 0.0_dp
        un = 0.0_dp
        call axis(n, coords, e, length, st)
        if (st%failed()) return
        ! k_n = RIGI_NOR, else e^T K e; K_t = P K P, P = I - e e^T (no RIGI_TAN here)
        call choc_stiffness(n, e(1:n), kdisc, kn, kt, rigi_nor)
        r(1:n) = ue(n + 1:2 * n) - ue(1:n)
        un = dot_product(r(1:n), e(1:n))
        closed = un + (length - (dist1 + dist2)) <= 0.0_dp
        ktan_n = 0.0_dp
        if (closed) then
            if (fn0 < 0.0_dp) fn = min(0.0_dp, fn0 + kn * (un - un0))
            du = un - un0
            if (abs(du) > epsilon(1.0_dp)) then
                ktan_n = abs(fn - fn0) / abs(du)
            else
                ktan_n = kn
            end if
        end if
        do i = 1, n
            f2(i) = fn * e(i) + dot_product(kt(i, 1:n), r(1:n))
        end do
        fe(1:n) = -f2(1:n)
        fe(n + 1:2 * n) = f2(1:n)
        if (elastic) then
            kc(1:n, 1:n) = kdisc
        else
            do j = 1, n
                do i = 1, n
                    kc(i, j) = ktan_n * e(i) * e(j) + kt(i, j)
                end do
            end do
        end if
        call pair_matrix(n, kc, ke)
    end subroutine dis_contact_seg2

    !> Unit axis node 1 -> node 2 and the length of the segment.
    subroutine axis(n, coords, e, length, st)
        integer(i4), intent(in) :: n
        real(dp), intent(in) :: coords(n, 2)
        real(dp), intent(out) :: e(MAX_DIM), length
        type(status_t), intent(out) :: st
        e = 0.0_dp
        e(1:n) = coords(:, 2) - coords(:, 1)
        length = norm2(e(1:n))
        if (.not. length > 0.0_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'DIS_CONTACT on a SEG2 of zero length: ' // &
                'no contact axis (the two nodes must be distinct)')
            return
        end if
        e(1:n) = e(1:n) / length
    end subroutine axis

end module element_dis_contact
