!> The geometry and tensor algebra of POST_RELEVE_T, as Code_Aster's postrele routines
!> compute it (operation order kept, so that values agree to the last bits):
!>  - path_abscissae      ABSC_CURV: the length along the listed nodes taken in turn (rvabsc);
!>  - plane_local_frames  REPERE='LOCAL': at each node the tangent of the polyline (mean of
!>                        its two segments inside, the segment at the ends) and the normal
!>                        z x t (rvrlln);
!>  - polar_frame         REPERE='POLAIRE': the radial and orthoradial directions of a point
!>                        about the origin (rvrthe);
!>  - cylindrical_frame   REPERE='CYLINDRIQUE': rows (e_r, e_z, e_theta) at a point (rvchn2);
!>  - user_frame          REPERE='UTILISATEUR': Code_Aster's matrot of ANGL_NAUT in degrees;
!>  - rotate_vector, rotate_tensor: u_local = P u, S_local = P S P^T (utpvgl, utpsgl);
!>  - tensor_invariants   INVARIANT: VMIS, TRESCA, TRACE, DETER (rvinvt);
!>  - path_statistics     MOYENNE: MOMENT_0, MOMENT_1, MINIMUM, MAXIMUM, MOYE_INT, MOYE_EXT
!>                        of a value along the path (rvpstm);
!>  - turned_value        a component in a plane frame (a, b) (rvcalq, LOCAL and POLAIRE);
!>  - traction            TRAC_DIR / TRAC_NOR: v.d or S d (rvpstd);
!>  - value_kind, tensor_row: what a frame turns in a field (vectors, tensors and their
!>                        component names). Shared by POST_RELEVE_T and MACR_LIGN_COUPE.
!> Tensors are (xx, yy, zz, xy, xz, yz), Code_Aster's SIXX .. SIYZ order.
module releve_frames
    use kinds, only: dp
    use element_discrete, only: nautical_rotation
    use field_transforms, only: symmetric_eigen
    use field_types, only: field_t, field_component
    implicit none
    private

    public :: path_abscissae, plane_local_frames, polar_frame, cylindrical_frame, user_frame, &
        rotate_vector, rotate_tensor, tensor_invariants, principal_stresses, path_statistics, &
        value_kind, tensor_row, turned_value, traction

    !> The kinds of value a frame turns (rvcalq's TQ): vectors, symmetric tensors, others.
    integer, parameter, public :: KIND_VECTOR = 1, KIND_TENSOR = 2, KIND_OTHER = 3

    character(len=*), parameter, public :: VECTOR_CMPS(6) = [character(len=3) :: 'DX', 'DY', 'DZ', &
        'DRX', 'DRY', 'DRZ']
    !> Names of each tensor slot (xx yy zz xy xz yz) by quantity, as rvche1 maps them.
    character(len=*), parameter, public :: TENSOR_SLOT_NAMES(6, 4) = reshape([character(len=4) :: &
        'SIXX', 'SIYY', 'SIZZ', 'SIXY', 'SIXZ', 'SIYZ', &
        'EPXX', 'EPYY', 'EPZZ', 'EPXY', 'EPXZ', 'EPYZ', &
        'NXX ', 'NYY ', 'NXY ', 'MXX ', 'MYY ', 'MXY ', &
        'N   ', 'VY  ', 'VZ  ', 'MT  ', 'MFY ', 'MFZ '], [6, 4])

contains

    !> Curvilinear abscissae of the points `x` (3, n) taken in turn, 0 at the first.
    pure function path_abscissae(x) result(s)
        real(dp), intent(in) :: x(:, :)
        real(dp) :: s(size(x, 2))
        real(dp) :: d(3)
        integer :: i
        if (size(s) == 0) return
        s(1) = 0.0_dp
        do i = 2, size(s)
            d = x(:, i) - x(:, i - 1)
            s(i) = s(i - 1) + sqrt(d(1) * d(1) + d(2) * d(2) + d(3) * d(3))
        end do
    end function path_abscissae

    !> The tangent t and normal n (z x t) at each point of the polyline `x` (3, n), in the
    !> xy plane: inside, the means of the two segments' directions; at the ends, the end
    !> segment's (rvrlln). A single point has t = (1, 0) by convention. A repeated point
    !> (a segment of zero length) has no direction.
    !>  ok : false when two consecutive points coincide
    pure subroutine plane_local_frames(x, t, n, ok)
        real(dp), intent(in) :: x(:, :)
        real(dp), intent(out) :: t(2, size(x, 2)), n(2, size(x, 2))
        logical, intent(out) :: ok
        real(dp) :: d(3), inv_length, ts(2), tp(2)
        integer :: i, m
        m = size(x, 2)
        ok = .true.
        t = 0.0_dp
        n = 0.0_dp
        if (m == 1) then
            t(:, 1) = [1.0_dp, 0.0_dp]
            n(:, 1) = [0.0_dp, 1.0_dp]
            return
        end if
        tp = 0.0_dp
        do i = 1, m
            if (i < m) then
                d = x(:, i + 1) - x(:, i)
                inv_length = sqrt(d(1) * d(1) + d(2) * d(2) + d(3) * d(3))
                if (.not. inv_length > 0.0_dp) then
                    ok = .false.
                    return
                end if
                inv_length = 1.0_dp / inv_length
                ts = [d(1) * inv_length, d(2) * inv_length]
            end if
            if (i == 1) then
                t(:, i) = ts
            else if (i < m) then
                t(:, i) = [0.5_dp * (ts(1) + tp(1)), 0.5_dp * (ts(2) + tp(2))]
            else
                t(:, i) = tp
            end if
            if (i == 1) then
                n(:, i) = [-ts(2), ts(1)]
            else if (i < m) then
                n(:, i) = [0.5_dp * (-ts(2) - tp(2)), 0.5_dp * (ts(1) + tp(1))]
            else
                n(:, i) = [-tp(2), tp(1)]
            end if
            tp = ts
        end do
    end subroutine plane_local_frames

    !> The radial direction r and the normal (z x r) at (px, py) (rvrthe); at the origin
    !> (within 1e-6) the global axes.
    pure subroutine polar_frame(px, py, r, n)
        real(dp), intent(in) :: px, py
        real(dp), intent(out) :: r(2), n(2)
        real(dp) :: rho, inv
        rho = sqrt(px * px + py * py)
        if (abs(rho) < 1.0e-6_dp) then
            r = [1.0_dp, 0.0_dp]
            n = [0.0_dp, 1.0_dp]
        else
            inv = 1.0_dp / rho
            r = [inv * px, inv * py]
            n = [-r(2), r(1)]
        end if
    end subroutine polar_frame

    !> The cylindrical frame at `p` about the axis through `origin` along the unit `axis`:
    !> rows e_r (from the axis to p), e_z (the axis), e_theta = e_z x e_r (rvchn2).
    !>  ok : false for a point on the axis (|e_r|^2 < 1e-6)
    pure subroutine cylindrical_frame(p, origin, axis, pgl, ok)
        real(dp), intent(in) :: p(3), origin(3), axis(3)
        real(dp), intent(out) :: pgl(3, 3)
        logical, intent(out) :: ok
        real(dp) :: er(3), et(3), dot, norm
        er = p - origin
        dot = er(1) * axis(1) + er(2) * axis(2) + er(3) * axis(3)
        er = er - dot * axis
        norm = er(1) * er(1) + er(2) * er(2) + er(3) * er(3)
        ok = norm >= 1.0e-6_dp
        pgl = 0.0_dp
        if (.not. ok) return
        er = er / sqrt(norm)
        et = [axis(2) * er(3) - axis(3) * er(2), axis(3) * er(1) - axis(1) * er(3), &
              axis(1) * er(2) - axis(2) * er(1)]
        pgl(1, :) = er
        pgl(2, :) = axis
        pgl(3, :) = et
    end subroutine cylindrical_frame

    !> The user frame of ANGL_NAUT (degrees): rows are the local axes (matrot).
    pure subroutine user_frame(degrees, pgl)
        real(dp), intent(in) :: degrees(3)
        real(dp), intent(out) :: pgl(3, 3)
        real(dp), parameter :: PER_DEGREE = 3.1415926535897932384626433832_dp / 180.0_dp
        call nautical_rotation(degrees * PER_DEGREE, pgl)
    end subroutine user_frame

    !> P v (utpvgl).
    pure function rotate_vector(pgl, v) result(w)
        real(dp), intent(in) :: pgl(3, 3), v(3)
        real(dp) :: w(3)
        integer :: i
        do i = 1, 3
            w(i) = pgl(i, 1) * v(1) + pgl(i, 2) * v(2) + pgl(i, 3) * v(3)
        end do
    end function rotate_vector

    !> P S P^T for S = (xx, yy, zz, xy, xz, yz), formed as utpsgl forms it.
    pure function rotate_tensor(pgl, s) result(r)
        real(dp), intent(in) :: pgl(3, 3), s(6)
        real(dp) :: r(6)
        real(dp) :: full(3, 3), local(3, 3)
        integer :: m, n, l
        full = reshape([s(1), s(4), s(5), s(4), s(2), s(6), s(5), s(6), s(3)], [3, 3])
        local = 0.0_dp
        do m = 1, 3
            do n = 1, m
                do l = 1, 3
                    local(m, n) = local(m, n) + pgl(m, l) * (full(1, l) * pgl(n, 1) + &
                        full(2, l) * pgl(n, 2) + full(3, l) * pgl(n, 3))
                end do
            end do
        end do
        r = [local(1, 1), local(2, 2), local(3, 3), local(2, 1), local(3, 1), local(3, 2)]
    end function rotate_tensor

    !> VMIS, TRESCA, TRACE, DETER of S = (xx, yy, zz, xy, xz, yz) (rvinvt).
    pure subroutine tensor_invariants(s, vmis, tresca, trace, det)
        real(dp), intent(in) :: s(6)
        real(dp), intent(out) :: vmis, tresca, trace, det
        real(dp) :: dev(6), inv, values(3)
        integer :: i
        call principal_stresses(s, values)
        tresca = max(abs(values(1) - values(2)), abs(values(1) - values(3)), &
                     abs(values(2) - values(3)))
        ! t1 (t2 t3 - t6 t6) - t4 (t4 t3 - t6 t5) + t5 (t4 t6 - t2 t5) (rvdet3)
        det = s(1) * (s(2) * s(3) - s(6) * s(6))
        det = det - s(4) * (s(4) * s(3) - s(6) * s(5))
        det = det + s(5) * (s(4) * s(6) - s(2) * s(5))
        trace = 0.0_dp
        do i = 1, 3
            trace = trace + s(i)
        end do
        dev = s
        do i = 1, 3
            dev(i) = s(i) - trace * (1.0_dp / 3.0_dp)
        end do
        inv = 0.0_dp
        do i = 1, 3
            inv = inv + dev(i) * dev(i)
        end do
        do i = 4, 6
            inv = inv + 2.0_dp * dev(i) * dev(i)
        end do
        vmis = sqrt(3.0_dp * inv * 0.5_dp)
    end subroutine tensor_invariants

    !> The principal values of S (increasing) and their unit directions (columns).
    pure subroutine principal_stresses(s, values, vectors)
        real(dp), intent(in) :: s(6)
        real(dp), intent(out) :: values(3)
        real(dp), intent(out), optional :: vectors(3, 3)
        real(dp) :: a(3, 3), v(3, 3)
        a(1, :) = [s(1), s(4), s(5)]
        a(2, :) = [s(4), s(2), s(6)]
        a(3, :) = [s(5), s(6), s(3)]
        call symmetric_eigen(a, values, v)
        if (present(vectors)) vectors = v
    end subroutine principal_stresses

    !> MOYENNE of the values `v` at the abscissae `s` (rvpstm): per segment whose two ends
    !> have a value, the length l, the trapezoid (t1 + t2) l and the first moment
    !> l/3 (t1 s1 + 4 tm sm + t2 s2) (s from the first point); then
    !>   MOMENT_0 = sum / (2 L),   MOMENT_1 = 6 (moment / L^2 - MOMENT_0),
    !>   MINIMUM, MAXIMUM of the ends, MOYE_INT = M0 - M1/2, MOYE_EXT = M0 + M1/2.
    !> The caller bounds the values and abscissae so that no sum overflows.
    !>  present : in, which points have a value
    !>  stats   : out, the six values in that order
    !>  missing : out, segments left out for a missing value (Code_Aster's alarm)
    !>  ok      : out, false when no segment has a length (one point, or every value
    !>            missing): there is no mean
    pure subroutine path_statistics(s, v, present, stats, missing, ok)
        real(dp), intent(in) :: s(:), v(:)
        logical, intent(in) :: present(:)
        real(dp), intent(out) :: stats(6)
        integer, intent(out) :: missing
        logical, intent(out) :: ok
        real(dp) :: m1, m2, lo, hi, length, s1, s2, s12, t1, t2
        integer :: i
        m1 = 0.0_dp
        m2 = 0.0_dp
        lo = 1.0e50_dp
        hi = -1.0e50_dp
        length = 0.0_dp
        missing = 0
        do i = 1, size(s) - 1
            if (.not. present(i)) then
                missing = missing + 1
                cycle
            end if
            if (.not. present(i + 1)) then
                if (i == size(s) - 1) missing = missing + 1
                cycle
            end if
            t1 = v(i)
            t2 = v(i + 1)
            s1 = s(i) - s(1)
            s2 = s(i + 1) - s(1)
            s12 = s2 - s1
            length = length + s12
            m1 = m1 + s12 * (t1 + t2)
            m2 = m2 + s12 / 3.0_dp * (t1 * s1 + 4.0_dp * ((t1 + t2) / 2.0_dp) * &
                ((s1 + s2) / 2.0_dp) + t2 * s2)
            hi = max(hi, t1, t2)
            lo = min(lo, t1, t2)
        end do
        stats = 0.0_dp
        ok = length > 0.0_dp
        if (.not. ok) return
        m1 = m1 / length
        m2 = m2 / (length * length)
        m1 = 0.5_dp * m1
        m2 = 6.0_dp * (m2 - m1)
        stats = [m1, m2, lo, hi, m1 - 0.5_dp * m2, m1 + 0.5_dp * m2]
    end subroutine path_statistics

    !> Vectors (DEPL_R, FORC_R), tensors (SIEF_R, EPSI_R) or others, as frames see them.
    pure integer function value_kind(quantity)
        character(len=*), intent(in) :: quantity
        select case (quantity)
        case ('DEPL_R', 'FORC_R')
            value_kind = KIND_VECTOR
        case ('SIEF_R', 'EPSI_R')
            value_kind = KIND_TENSOR
        case default
            value_kind = KIND_OTHER
        end select
    end function value_kind

    !> Which row of TENSOR_SLOT_NAMES names the field's tensor components: the first row
    !> with a component the field has; 0 for none.
    integer function tensor_row(f) result(row)
        type(field_t), intent(in) :: f
        integer :: j
        do row = 1, size(TENSOR_SLOT_NAMES, 2)
            do j = 1, 6
                if (field_component(f, trim(TENSOR_SLOT_NAMES(j, row))) > 0) return
            end do
        end do
        row = 0
    end function tensor_row

    !> One component in the plane frame (a, b) (rvcalq, V3 and T3).
    pure real(dp) function turned_value(kind, j, v, a, b) result(val)
        integer, intent(in) :: kind, j
        real(dp), intent(in) :: v(:), a(2), b(2)
        real(dp) :: txx, tyy, txy
        if (kind == KIND_VECTOR) then
            select case (j)
            case (1)
                val = a(1) * v(1) + a(2) * v(2)
            case (2)
                val = b(1) * v(1) + b(2) * v(2)
            case (4)
                val = a(1) * v(4) + a(2) * v(5)
            case (5)
                val = b(1) * v(4) + b(2) * v(5)
            case default
                val = v(j)
            end select
        else
            txx = v(1); tyy = v(2); txy = v(4)
            select case (j)
            case (1)
                val = a(1) * (a(1) * txx + a(2) * txy) + a(2) * (a(1) * txy + a(2) * tyy)
            case (2)
                val = b(1) * (b(1) * txx + b(2) * txy) + b(2) * (b(1) * txy + b(2) * tyy)
            case (4)
                val = a(1) * (b(1) * txx + b(2) * txy) + a(2) * (b(1) * txy + b(2) * tyy)
            case (5)
                val = a(1) * v(5) + a(2) * v(6)
            case (6)
                val = b(1) * v(5) + b(2) * v(6)
            case default
                val = v(3)
            end select
        end if
    end function turned_value

    !> v.d for a vector, S d for a tensor (xx yy zz xy xz yz), the terms of zero direction
    !> components left out as rvpstd leaves them out.
    pure subroutine traction(kind, v, d, q)
        integer, intent(in) :: kind
        real(dp), intent(in) :: v(:), d(3)
        real(dp), intent(out) :: q(:)
        integer, parameter :: ROWS(3, 3) = reshape([1, 4, 5, 4, 2, 6, 5, 6, 3], [3, 3])
        integer :: i
        q = 0.0_dp
        if (kind == KIND_VECTOR) then
            q(1) = dot(v(1:3))
        else
            do i = 1, 3
                q(i) = dot([v(ROWS(1, i)), v(ROWS(2, i)), v(ROWS(3, i))])
            end do
        end if
    contains
        pure real(dp) function dot(w)
            real(dp), intent(in) :: w(3)
            integer :: j
            logical :: started
            dot = 0.0_dp
            started = .false.
            do j = 1, 3
                if (.not. abs(d(j)) > 0.0_dp) cycle
                if (started) then
                    dot = dot + w(j) * d(j)
                else
                    dot = w(j) * d(j)
                    started = .true.
                end if
            end do
        end function dot
    end subroutine traction

end module releve_frames
