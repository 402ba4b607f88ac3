!> Thermal strains of a material (Code_Aster R4.08.01 and DEFI_MATERIAU U4.43.01):
!>  - ELAS ALPHA: eps = ALPHA (T - T_ref), T_ref the VALE_REF of AFFE_VARC;
!>  - ELAS_FO ALPHA, a function of TEMP given at its definition temperature T_def
!>    (TEMP_DEF_ALPHA): Code_Aster turns it into the coefficient about T_ref (alfint),
!>      alpha^(T) = (ALPHA(T) (T - T_def) - ALPHA(T_ref) (T_ref - T_def)) / (T - T_ref),
!>    computed at the points of a tabulated function and interpolated linearly between
!>    them (at a point closer to T_ref than ELAS_FO PRECISION, 1 by default, from the
!>    slopes around it); eps = alpha^(T)
!>    (T - T_ref). A formula is evaluated at T itself. Without TEMP_DEF_ALPHA the function
!>    is taken as the coefficient about T_ref.
!> A material without ALPHA has no thermal strain.
!>
!> The strains of the other command variables (Code_Aster R7.01.12 and DEFI_MATERIAU ELAS /
!> ELAS_FO, U4.43.01; isotropic, like the thermal one, and added to it):
!>  - the endogenous shrinkage of the hydration HYDR (AFFE_VARC NOM_VARC='HYDR'):
!>      eps = -B_ENDOGE h;
!>  - the desiccation shrinkage of the drying SECH (NOM_VARC='SECH', VALE_REF = S_ref):
!>      eps = -K_DESSIC (S_ref - S).
!> B_ENDOGE and K_DESSIC are reals of ELAS or ELAS_FO, 0 by default (no strain).
module model_thermal
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: real_e13
    use number_limits, only: product_fits, MAX_TEMPERATURE, MAX_STRAIN
    use function_concept, only: function_concept_t, param_binding_t
    use tabulated_function, only: tabulated_function_t
    use model_material, only: material_t, behaviour_number, behaviour_function, &
        has_behaviour
    implicit none
    private

    !> Code_Aster's default of ELAS_FO PRECISION (alfint's distance to T_ref).
    real(dp), parameter :: DEFAULT_PRECISION = 1.0_dp
    !> The smallest distance to T_ref alfint divides by (a PRECISION below it is raised to
    !> it, so that the quotient of bounded numbers stays finite; 1e-30 K is far below any
    !> temperature a deck distinguishes).
    real(dp), parameter :: MIN_PRECISION = 1.0e-30_dp

    public :: has_thermal_expansion, thermal_strain, shrinkage_coefficient, shrinkage_strain, &
        shrinks_with

    !> The coefficients of the shrinkage strains (module header), by command variable.
    character(len=*), parameter, public :: SHRINKAGE_KEY_HYDR = 'B_ENDOGE', &
        SHRINKAGE_KEY_SECH = 'K_DESSIC'

contains

    !> True when the material gives a thermal expansion coefficient (ELAS or ELAS_FO ALPHA).
    logical function has_thermal_expansion(mat)
        type(material_t), intent(in) :: mat
        real(dp) :: alpha
        logical :: found
        call behaviour_number(mat, 'ELAS', 'ALPHA', alpha, found)
        if (.not. found) found = associated(behaviour_function(mat, 'ELAS_FO', 'ALPHA'))
        if (.not. found .and. has_behaviour(mat, 'ELAS_FO')) &
            call behaviour_number(mat, 'ELAS_FO', 'ALPHA', alpha, found)
        has_thermal_expansion = found
    end function has_thermal_expansion

    !> The isotropic thermal strain of the material at temperature t (module header).
    !>  tref : in, the reference temperature (AFFE_VARC VALE_REF)
    !>  eps  : out, the strain (0 without ALPHA)
    !>  st   : out, an ALPHA function failing at t, naming it
    subroutine thermal_strain(mat, t, tref, eps, st)
        type(material_t), intent(in) :: mat
        real(dp), intent(in) :: t, tref
        real(dp), intent(out) :: eps
        type(status_t), intent(out) :: st
        real(dp) :: alpha, tdef, prec, eps_ref
        logical :: found, has_def
        class(function_concept_t), pointer :: f
        eps = 0.0_dp
        ! the temperatures are bounded before any difference or product is formed from them
        ! (number_limits: a temperature field of 1e308 would overflow D alpha (T - T_ref))
        if (.not. temperature_fits(t, 'TEMP', st)) return
        if (.not. temperature_fits(tref, 'VALE_REF', st)) return
        call behaviour_number(mat, 'ELAS', 'ALPHA', alpha, found)
        if (found) then
            call strain_of(alpha, t - tref, eps, st)
            return
        end if
        f => behaviour_function(mat, 'ELAS_FO', 'ALPHA')
        if (.not. associated(f)) then
            call behaviour_number(mat, 'ELAS_FO', 'ALPHA', alpha, found)
            if (found) call strain_of(alpha, t - tref, eps, st)
            return
        end if
        call behaviour_number(mat, 'ELAS_FO', 'TEMP_DEF_ALPHA', tdef, has_def)
        if (.not. has_def) then
            call evaluate_alpha(f, t, alpha, st)
            if (st%ok()) call strain_of(alpha, t - tref, eps, st)
            return
        end if
        if (.not. temperature_fits(tdef, 'TEMP_DEF_ALPHA', st)) return
        call behaviour_number(mat, 'ELAS_FO', 'PRECISION', prec, found)
        if (.not. found) prec = DEFAULT_PRECISION
        select type (f)
        type is (tabulated_function_t)
            if (any(abs(f%x) > MAX_TEMPERATURE) .or. any(abs(f%y) > MAX_STRAIN)) then
                call set_error(st, STATUS_MODEL_ERROR, 'ELAS_FO/ALPHA: its temperatures ' // &
                    'must lie within +-' // real_e13(MAX_TEMPERATURE) // ' and its values ' // &
                    'within +-' // real_e13(MAX_STRAIN) // ' for a thermal strain')
                return
            end if
            call tabulated_strain(f, t, tref, tdef, max(prec, MIN_PRECISION), eps_ref)
            call strain_of(1.0_dp, eps_ref, eps, st)
        class default
            call evaluate_alpha(f, t, alpha, st)
            if (st%ok()) call strain_of(alpha, t - tdef, eps, st)
            if (st%failed()) return
            call evaluate_alpha(f, tref, alpha, st)
            if (st%ok()) call strain_of(alpha, tref - tdef, eps_ref, st)
            if (st%ok()) eps = eps - eps_ref
        end select
    end subroutine thermal_strain

    !> The shrinkage coefficient `key` (SHRINKAGE_KEY_HYDR: B_ENDOGE, SHRINKAGE_KEY_SECH:
    !> K_DESSIC) of the material's ELAS or ELAS_FO, 0 when it gives none.
    real(dp) function shrinkage_coefficient(mat, key) result(coef)
        type(material_t), intent(in) :: mat
        character(len=*), intent(in) :: key
        logical :: found
        call behaviour_number(mat, 'ELAS', key, coef, found)
        if (.not. found) call behaviour_number(mat, 'ELAS_FO', key, coef, found)
        if (.not. found) coef = 0.0_dp
    end function shrinkage_coefficient

    !> True when the material's shrinkage coefficient `key` is not zero.
    logical function shrinks_with(mat, key)
        type(material_t), intent(in) :: mat
        character(len=*), intent(in) :: key
        shrinks_with = abs(shrinkage_coefficient(mat, key)) > 0.0_dp
    end function shrinks_with

    !> The shrinkage strain of the material (module header) for command variable value v:
    !>  key  : in, SHRINKAGE_KEY_HYDR (eps = -B_ENDOGE v) or SHRINKAGE_KEY_SECH
    !>         (eps = -K_DESSIC (vref - v))
    !>  vref : in, the reference (SECH's VALE_REF; unused for HYDR)
    !>  st   : out, a value beyond MAX_TEMPERATURE or a strain beyond MAX_STRAIN, named
    subroutine shrinkage_strain(mat, key, v, vref, eps, st)
        type(material_t), intent(in) :: mat
        character(len=*), intent(in) :: key
        real(dp), intent(in) :: v, vref
        real(dp), intent(out) :: eps
        type(status_t), intent(out) :: st
        real(dp) :: coef, dv
        eps = 0.0_dp
        coef = shrinkage_coefficient(mat, key)
        if (.not. abs(coef) > 0.0_dp) return
        ! the values are bounded as temperatures before their difference is formed
        if (.not. temperature_fits(v, merge('HYDR', 'SECH', key == SHRINKAGE_KEY_HYDR), st)) &
            return
        if (.not. temperature_fits(vref, 'VALE_REF', st)) return
        ! eps = -B_ENDOGE h, or -K_DESSIC (S_ref - S) = K_DESSIC (S - S_ref)
        dv = -v
        if (key /= SHRINKAGE_KEY_HYDR) dv = v - vref
        if (product_fits(coef, dv)) then
            if (abs(coef * dv) <= MAX_STRAIN) then
                eps = coef * dv
                return
            end if
        end if
        call set_error(st, STATUS_MODEL_ERROR, 'the shrinkage strain of ' // key // ' = ' // &
            real_e13(coef) // ' is beyond ' // real_e13(MAX_STRAIN) // ' (check ' // key // &
            ' and the field of AFFE_VARC ' // merge('HYDR', 'SECH', &
            key == SHRINKAGE_KEY_HYDR) // ')')
    end subroutine shrinkage_strain

    !> True when |t| <= MAX_TEMPERATURE; otherwise st names the quantity.
    logical function temperature_fits(t, what, st)
        real(dp), intent(in) :: t
        character(len=*), intent(in) :: what
        type(status_t), intent(inout) :: st
        temperature_fits = abs(t) <= MAX_TEMPERATURE
        if (.not. temperature_fits) call set_error(st, STATUS_MODEL_ERROR, what // ' = ' // &
            real_e13(t) // ' is beyond the temperatures parasol takes for a thermal strain ' // &
            '(|T| <= ' // real_e13(MAX_TEMPERATURE) // ')')
    end function temperature_fits

    !> eps = alpha dt when the product fits and |eps| <= MAX_STRAIN, else an error.
    subroutine strain_of(alpha, dt, eps, st)
        real(dp), intent(in) :: alpha, dt
        real(dp), intent(out) :: eps
        type(status_t), intent(inout) :: st
        eps = 0.0_dp
        if (product_fits(alpha, dt)) then
            if (abs(alpha * dt) <= MAX_STRAIN) then
                eps = alpha * dt
                return
            end if
        end if
        call set_error(st, STATUS_MODEL_ERROR, 'the thermal strain ALPHA (T - T_ref) = ' // &
            real_e13(alpha) // ' x ' // real_e13(dt) // ' is beyond ' // &
            real_e13(MAX_STRAIN) // ' (check ALPHA and the temperatures of AFFE_VARC)')
    end subroutine strain_of

    subroutine evaluate_alpha(f, t, alpha, st)
        class(function_concept_t), intent(in) :: f
        real(dp), intent(in) :: t
        real(dp), intent(out) :: alpha
        type(status_t), intent(out) :: st
        type(param_binding_t) :: binding
        call f%bind(['TEMP'], binding)
        call f%evaluate(binding, [t], alpha, st)
        if (st%failed()) call set_error(st, st%code, 'ELAS_FO/ALPHA at TEMP = ' // &
            real_e13(t) // ': ' // st%message)
    end subroutine evaluate_alpha

    ! Code_Aster's alfint on a tabulated ALPHA, then alpha^(t) (t - tref).
    pure subroutine tabulated_strain(f, t, tref, tdef, prec, eps)
        type(tabulated_function_t), intent(in) :: f
        real(dp), intent(in) :: t, tref, tdef, prec
        real(dp), intent(out) :: eps
        real(dp), allocatable :: a(:)
        real(dp) :: alfref, w
        integer(i4) :: i, n
        n = size(f%x, kind=i4)
        alfref = interpolate(f%x, f%y, tref)
        allocate (a(n))
        do i = 1, n
            if (abs(f%x(i) - tref) >= prec) then
                a(i) = (f%y(i) * (f%x(i) - tdef) - alfref * (tref - tdef)) / (f%x(i) - tref)
            else
                a(i) = slope_at(i) * (tref - tdef) + alfref
            end if
        end do
        if (n == 1) then
            eps = a(1) * (t - tref)
            return
        end if
        ! linear interpolation of the transformed table (constant beyond its ends)
        if (t <= f%x(1)) then
            eps = a(1) * (t - tref)
        else if (t >= f%x(n)) then
            eps = a(n) * (t - tref)
        else
            do i = 1, n - 1
                if (t <= f%x(i + 1)) exit
            end do
            w = (t - f%x(i)) / (f%x(i + 1) - f%x(i))
            eps = ((1.0_dp - w) * a(i) + w * a(i + 1)) * (t - tref)
        end if
    contains
        ! d alpha / dT at T_ref from the neighbours of point k (both sides averaged, as
        ! alfint; a neighbour at T_ref itself, or closer than MIN_PRECISION, does not count:
        ! the quotient stays finite)
        pure real(dp) function slope_at(k) result(s)
            integer(i4), intent(in) :: k
            real(dp) :: total
            integer(i4) :: terms
            total = 0.0_dp
            terms = 0
            if (k < n) then
                if (abs(f%x(k + 1) - tref) >= MIN_PRECISION) then
                    total = total + (f%y(k + 1) - alfref) / (f%x(k + 1) - tref)
                    terms = terms + 1
                end if
            end if
            if (k > 1) then
                if (abs(f%x(k - 1) - tref) >= MIN_PRECISION) then
                    total = total + (alfref - f%y(k - 1)) / (tref - f%x(k - 1))
                    terms = terms + 1
                end if
            end if
            s = 0.0_dp
            if (terms > 0) s = total / real(terms, dp)
        end function slope_at
    end subroutine tabulated_strain

    pure real(dp) function interpolate(x, y, t) result(v)
        real(dp), intent(in) :: x(:), y(:), t
        integer(i4) :: i, n
        n = size(x, kind=i4)
        if (n == 1 .or. t <= x(1)) then
            v = y(1)
        else if (t >= x(n)) then
            v = y(n)
        else
            do i = 1, n - 1
                if (t <= x(i + 1)) exit
            end do
            v = y(i) + (y(i + 1) - y(i)) * (t - x(i)) / (x(i + 1) - x(i))
        end if
    end function interpolate

end module model_thermal
