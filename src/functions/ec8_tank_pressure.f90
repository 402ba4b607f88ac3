!> The hydrodynamic pressure on the wall of a cylindrical tank under an earthquake, after
!> Eurocode 8 part 4 (EN 1998-4) annex A, as Code_Aster's DEFI_PRES_EC8 defines it (U4.44.31;
!> its operator cites the DERESMA formulas B.5-53, B.5-55, B.5-56).
!>
!> The tank's axis is the global Z axis through X = Y = 0; its bottom is at Z = Z_FOND, the
!> water height is H, the radius R. A point (x, y, z) has r = sqrt(x^2 + y^2), z measured
!> from the bottom, and the angle theta from the +X axis, cos(theta) = x / r (the horizontal
!> earthquake acts along X; cos(theta) = 1 on the axis, r^2 <= 1e-6, as Code_Aster). With
!> phi = pi z / (2 H), l_n = 2n + 1, x_n = l_n pi R / (2 H):
!>   rigid impulsive (horizontal)   p_ir = C0 rho A_rh H cos(theta),
!>       C0 = sum_{n=0}^{20} 8 / pi^2 (-1)^n / l_n^2 I1(l_n pi r / 2H) / I1'(x_n) cos(l_n phi)
!>   flexible impulsive (horizontal) p_if = (r/R) cos(theta) rho H psi (A_fhn - A_rh)
!>                                          sum_{n=0}^{1} d_n cos(l_n phi)
!>       d_n = 4/pi s_n I1(x_n) / (l_n I1'(x_n)),  b_n = 8/pi^2 (-1)^n I1(x_n) / (l_n^2 I1'(x_n)),
!>       s_n = (1/H) int_0^H sin(phi) cos(l_n phi) dz, and for the shell of thickness e and
!>       density rho_s (m = rho_s e / (rho H)):
!>       psi = (2m/pi + sum b_n s_n) / (m/2 + sum d_n s_n)  (the ratio of the integrals over
!>       the height that Code_Aster computes by quadrature, here in closed form)
!>   convective (first sloshing mode, lambda_1 = 1.841 the first root of J1')
!>       p_c1 = 0.8371 rho R A_c1 cosh(lambda_1 z/R) / cosh(lambda_1 H/R)
!>              J1(lambda_1 r/R) / J1(lambda_1) cos(theta)    (0.8371 = 2 / (lambda_1^2 - 1))
!>   rigid vertical    p_rv = rho A_rv (H - z)
!>   flexible vertical p_fv = 0.815 f2 rho H cos(phi) (A_fv - A_rv),
!>       f2 = 1.078 + 0.274 ln(H/R) when H/R > 0.8, else 1
!>   hydrostatic       p_h = rho g (H - z)
!> and the total, the horizontal parts combined by the square root of the sum of squares with
!> the sign of cos(theta), the vertical ones by Newmark's 40 % rule (NEWMARK 'PC+' / 'PC-'):
!>   p = sign(cos theta) sqrt((p_ir + p_if)^2 + p_c1^2) +- 0.4 (p_rv + p_fv) + p_h + P_SURF_LIBR
!> Above the free surface (z > H) the pressure is PRES_SURF_LIBR alone; below the bottom it
!> is an error, as is a point farther than R (1 + 1 %) from the axis (Code_Aster CHARGES7_17,
!> CHARGES7_19), a negative EP or RHO (EP = 0: a shell without mass).
module ec8_tank_pressure
    use kinds, only: dp
    use strings, only: to_text
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use modified_bessel, only: scaled_i1, scaled_i1_derivative
    use number_limits, only: MAX_LENGTH, MAX_MODULUS
    implicit none
    private

    real(dp), parameter :: PI = acos(-1.0_dp)
    !> Terms of the rigid impulsive series (Code_Aster: n = 0 .. 20) and of the flexible one
    !> (Code_Aster: n = 0 .. 1, "N = 1 for now").
    integer, parameter, public :: EC8_RIGID_TERMS = 20, EC8_FLEXIBLE_TERMS = 1
    !> First sloshing mode: lambda_1 (first root of J1', rounded as EC8 and Code_Aster give
    !> it) and 2 / (lambda_1^2 - 1) as they give it.
    real(dp), parameter :: LAMBDA_1 = 1.841_dp, CONVECTIVE_FACTOR = 0.8371_dp
    !> Flexible vertical mode: 0.815 f2, f2 = F2_BASE + F2_SLOPE ln(H/R) above H/R = 0.8.
    real(dp), parameter :: VERTICAL_FACTOR = 0.815_dp, F2_BASE = 1.078_dp, &
        F2_SLOPE = 0.274_dp, F2_SLENDER = 0.8_dp
    !> Newmark's combination coefficient of the vertical parts.
    real(dp), parameter :: NEWMARK_COEF = 0.4_dp
    !> How far beyond the radius a point may lie (Code_Aster: 1 %).
    real(dp), parameter, public :: EC8_RADIUS_TOLERANCE = 0.01_dp
    !> Below this r^2 the point is on the axis: cos(theta) = 1 (Code_Aster's threshold).
    real(dp), parameter :: AXIS_R2 = 1.0e-6_dp
    !> Largest exponent of e^(a - b) in I1(a) / I1'(b) (a point just beyond the wall of a very
    !> flat tank): beyond it the pressure is refused rather than formed.
    real(dp), parameter :: MAX_GROWTH_EXPONENT = 50.0_dp

    !> The tank and the earthquake of one DEFI_PRES_EC8.
    type, public :: ec8_tank_t
        real(dp) :: z_bottom = 0.0_dp, radius = 1.0_dp, height = 1.0_dp, rho = 1.0_dp
        real(dp) :: a_rh = 0.0_dp, a_fhn = 0.0_dp, a_fv = 0.0_dp, a_rv = 0.0_dp
        real(dp) :: a_c1 = 0.0_dp, gravity = 0.0_dp, p_free = 0.0_dp
        real(dp) :: newmark_sign = 1.0_dp          !< +1 'PC+', -1 'PC-'
    end type ec8_tank_t

    !> The parts of the pressure at one point (their names in Code_Aster's EVAL tables).
    type, public :: ec8_parts_t
        real(dp) :: pir = 0.0_dp, pif = 0.0_dp, pc1 = 0.0_dp, prv = 0.0_dp, pfv = 0.0_dp
        real(dp) :: phydr = 0.0_dp, total = 0.0_dp
    end type ec8_parts_t

    public :: ec8_pressure, ec8_pressure_above_bottom

contains

    !> The pressure at (x, y, z) on a shell of thickness ep and density rho_s.
    !>  parts : out, the parts and the total (all 0 but total = p_free above the surface)
    !>  st    : out, z below the bottom, r beyond R (1 + 1 %), a thickness or a density < 0
    !>          (or beyond number_limits)
    subroutine ec8_pressure(tank, x, y, z, ep, rho_s, parts, st)
        type(ec8_tank_t), intent(in) :: tank
        real(dp), intent(in) :: x, y, z, ep, rho_s
        type(ec8_parts_t), intent(out) :: parts
        type(status_t), intent(out) :: st
        if (z < tank%z_bottom) then
            call set_error(st, STATUS_MODEL_ERROR, 'the point is below the bottom of the ' // &
                'tank: Z = ' // to_text(z) // ' < Z_FOND = ' // to_text(tank%z_bottom) // &
                ' (apply the pressure to cells of the tank only)')
            return
        end if
        call ec8_pressure_above_bottom(tank, x, y, z - tank%z_bottom, ep, rho_s, parts, st)
    end subroutine ec8_pressure

    !> The same at height zb >= 0 above the bottom (DEFI_PRES_EC8 EVAL's LIST_H).
    subroutine ec8_pressure_above_bottom(tank, x, y, zb, ep, rho_s, parts, st)
        type(ec8_tank_t), intent(in) :: tank
        real(dp), intent(in) :: x, y, zb, ep, rho_s
        type(ec8_parts_t), intent(out) :: parts
        type(status_t), intent(out) :: st
        real(dp) :: r, h, cos_t, phi, horizontal
        h = tank%height
        if (zb > h) then
            parts%total = tank%p_free
            return
        end if
        r = hypot(x, y)
        if (r > tank%radius * (1.0_dp + EC8_RADIUS_TOLERANCE)) then
            call set_error(st, STATUS_MODEL_ERROR, 'the point is outside the tank: its ' // &
                'distance to the axis (X = Y = 0) is ' // to_text(r) // ' > RAYON = ' // &
                to_text(tank%radius) // ' (+1 %)')
            return
        end if
        ! EP = 0 is a shell without mass (m = 0): psi stays finite, its denominator > 0
        if (.not. (ep >= 0.0_dp .and. ep <= MAX_LENGTH)) then
            call set_error(st, STATUS_MODEL_ERROR, 'the shell thickness EP = ' // &
                to_text(ep) // ' must be >= 0 and <= ' // to_text(MAX_LENGTH))
            return
        end if
        if (.not. (rho_s >= 0.0_dp .and. rho_s <= MAX_MODULUS)) then
            call set_error(st, STATUS_MODEL_ERROR, 'the shell density RHO = ' // &
                to_text(rho_s) // ' must be >= 0 and <= ' // to_text(MAX_MODULUS))
            return
        end if
        cos_t = 1.0_dp
        if (r * r > AXIS_R2) cos_t = max(-1.0_dp, min(1.0_dp, x / r))
        phi = PI * zb / (2.0_dp * h)
        call rigid_impulsive(tank, r, phi, cos_t, parts%pir, st)
        if (st%failed()) return
        parts%pif = flexible_impulsive(tank, r, phi, cos_t, ep, rho_s)
        parts%pc1 = convective(tank, r, zb, cos_t)
        parts%prv = tank%rho * tank%a_rv * (h - zb)
        parts%pfv = flexible_vertical(tank, phi)
        parts%phydr = tank%rho * tank%gravity * (h - zb)
        horizontal = hypot(parts%pir + parts%pif, parts%pc1)
        if (cos_t < 0.0_dp) horizontal = -horizontal
        parts%total = horizontal + tank%newmark_sign * NEWMARK_COEF * (parts%prv + parts%pfv) &
            + tank%p_free + parts%phydr
    end subroutine ec8_pressure_above_bottom

    !> p_ir = C0 rho A_rh H cos(theta), the series C0 summed over n = 0 .. 20.
    subroutine rigid_impulsive(tank, r, phi, cos_t, pir, st)
        type(ec8_tank_t), intent(in) :: tank
        real(dp), intent(in) :: r, phi, cos_t
        real(dp), intent(out) :: pir
        type(status_t), intent(out) :: st
        real(dp) :: c0, a, b, growth, l
        integer :: n
        c0 = 0.0_dp
        pir = 0.0_dp
        do n = 0, EC8_RIGID_TERMS
            l = real(2 * n + 1, dp)
            a = l * PI * r / (2.0_dp * tank%height)
            b = l * PI * tank%radius / (2.0_dp * tank%height)
            growth = a - b          ! I1(a) / I1'(b) = e^-a I1(a) / (e^-b I1'(b)) e^(a - b)
            if (growth > MAX_GROWTH_EXPONENT) then
                call set_error(st, STATUS_MODEL_ERROR, 'the point lies beyond the wall ' // &
                    '(r = ' // to_text(r) // ' > RAYON = ' // to_text(tank%radius) // &
                    ') where the impulsive pressure of a tank this flat (HAUT_EAU / RAYON = ' &
                    // to_text(tank%height / tank%radius) // ') grows beyond bounds')
                return
            end if
            c0 = c0 + 8.0_dp / PI**2 * sign_of_order(n) / l**2 * scaled_i1(a) / &
                scaled_i1_derivative(b) * exp(growth) * cos(l * phi)
        end do
        pir = c0 * tank%rho * tank%a_rh * tank%height * cos_t
    end subroutine rigid_impulsive

    !> p_if = (r/R) cos(theta) rho H psi (A_fhn - A_rh) sum_{n=0}^{1} d_n cos(l_n phi).
    real(dp) function flexible_impulsive(tank, r, phi, cos_t, ep, rho_s) result(pif)
        type(ec8_tank_t), intent(in) :: tank
        real(dp), intent(in) :: r, phi, cos_t, ep, rho_s
        real(dp) :: d(0:EC8_FLEXIBLE_TERMS), bp(0:EC8_FLEXIBLE_TERMS), s(0:EC8_FLEXIBLE_TERMS)
        real(dp) :: m, psi, total, ratio, l
        integer :: n
        total = 0.0_dp
        do n = 0, EC8_FLEXIBLE_TERMS
            l = real(2 * n + 1, dp)
            ratio = scaled_i1(l * PI * tank%radius / (2.0_dp * tank%height)) / &
                scaled_i1_derivative(l * PI * tank%radius / (2.0_dp * tank%height))
            s(n) = mode_overlap(n)
            d(n) = 4.0_dp / PI * s(n) * ratio / l
            bp(n) = 8.0_dp / PI**2 * sign_of_order(n) * ratio / l**2
            total = total + d(n) * cos(l * phi)
        end do
        ! m = rho_s e / (rho H): the shell's mass against the water's
        m = (rho_s / tank%rho) * (ep / tank%height)
        psi = (2.0_dp * m / PI + sum(bp * s)) / (0.5_dp * m + sum(d * s))
        pif = (r / tank%radius) * cos_t * tank%rho * tank%height * psi * &
            (tank%a_fhn - tank%a_rh) * total
    end function flexible_impulsive

    !> s_n = (1/H) int_0^H sin(pi z / 2H) cos((2n+1) pi z / 2H) dz, in closed form:
    !> 1/pi for n = 0; ((1 - (-1)^(n+1)) / (n+1) - (1 - (-1)^n) / n) / (2 pi) for n >= 1.
    pure real(dp) function mode_overlap(n) result(s)
        integer, intent(in) :: n
        if (n == 0) then
            s = 1.0_dp / PI
        else
            s = ((1.0_dp + sign_of_order(n)) / real(n + 1, dp) - &
                 (1.0_dp - sign_of_order(n)) / real(n, dp)) / (2.0_dp * PI)
        end if
    end function mode_overlap

    !> p_c1 = 0.8371 rho R A_c1 cosh(l1 z/R) / cosh(l1 H/R) J1(l1 r/R) / J1(l1) cos(theta);
    !> the ratio of the cosh as e^(l1 (z - H)/R) (1 + e^(-2 l1 z/R)) / (1 + e^(-2 l1 H/R)),
    !> finite for any H/R.
    real(dp) function convective(tank, r, zb, cos_t) result(pc1)
        type(ec8_tank_t), intent(in) :: tank
        real(dp), intent(in) :: r, zb, cos_t
        real(dp) :: k, cosh_ratio
        k = LAMBDA_1 / tank%radius
        cosh_ratio = exp(k * (zb - tank%height)) * (1.0_dp + exp(-2.0_dp * k * zb)) / &
            (1.0_dp + exp(-2.0_dp * k * tank%height))
        pc1 = CONVECTIVE_FACTOR * tank%rho * tank%radius * tank%a_c1 * cosh_ratio * &
            bessel_j1(k * r) / bessel_j1(LAMBDA_1) * cos_t
    end function convective

    !> p_fv = 0.815 f2 rho H cos(phi) (A_fv - A_rv).
    real(dp) function flexible_vertical(tank, phi) result(pfv)
        type(ec8_tank_t), intent(in) :: tank
        real(dp), intent(in) :: phi
        real(dp) :: f2, slenderness
        slenderness = tank%height / tank%radius
        f2 = 1.0_dp
        if (slenderness > F2_SLENDER) f2 = F2_BASE + F2_SLOPE * log(slenderness)
        pfv = VERTICAL_FACTOR * f2 * tank%height * tank%rho * cos(phi) * (tank%a_fv - tank%a_rv)
    end function flexible_vertical

    !> (-1)^n.
    pure real(dp) function sign_of_order(n)
        integer, intent(in) :: n
        sign_of_order = merge(1.0_dp, -1.0_dp, mod(n, 2) == 0)
    end function sign_of_order

end module ec8_tank_pressure
