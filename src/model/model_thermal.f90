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
module model_thermal
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: real_e13
    use function_concept, only: function_concept_t, param_binding_t
    use tabulated_function, only: tabulated_function_t
    use model_material, only: material_t, behaviour_number, behaviour_function, &
        has_behaviour
    implicit none
    private

    !> Code_Aster's default of ELAS_FO PRECISION (alfint's distance to T_ref).
    real(dp), parameter :: DEFAULT_PRECISION = 1.0_dp

    public :: has_thermal_expansion, thermal_strain

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
        real(dp) :: alpha, tdef, prec
        logical :: found, has_def
        class(function_concept_t), pointer :: f
        eps = 0.0_dp
        call behaviour_number(mat, 'ELAS', 'ALPHA', alpha, found)
        if (found) then
            eps = alpha * (t - tref)
            return
        end if
        f => behaviour_function(mat, 'ELAS_FO', 'ALPHA')
        if (.not. associated(f)) then
            call behaviour_number(mat, 'ELAS_FO', 'ALPHA', alpha, found)
            if (found) eps = alpha * (t - tref)
            return
        end if
        call behaviour_number(mat, 'ELAS_FO', 'TEMP_DEF_ALPHA', tdef, has_def)
        if (.not. has_def) then
            call evaluate_alpha(f, t, alpha, st)
            eps = alpha * (t - tref)
            return
        end if
        call behaviour_number(mat, 'ELAS_FO', 'PRECISION', prec, found)
        if (.not. found) prec = DEFAULT_PRECISION
        select type (f)
        type is (tabulated_function_t)
            call tabulated_strain(f, t, tref, tdef, prec, eps)
        class default
            call evaluate_alpha(f, t, alpha, st)
            if (st%failed()) return
            eps = alpha * (t - tdef)
            call evaluate_alpha(f, tref, alpha, st)
            eps = eps - alpha * (tref - tdef)
        end select
    end subroutine thermal_strain

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
        ! alfint; a neighbour at T_ref itself does not count)
        pure real(dp) function slope_at(k) result(s)
            integer(i4), intent(in) :: k
            real(dp) :: total
            integer(i4) :: terms
            total = 0.0_dp
            terms = 0
            if (k < n) then
                if (abs(f%x(k + 1) - tref) > 0.0_dp) then
                    total = total + (f%y(k + 1) - alfref) / (f%x(k + 1) - tref)
                    terms = terms + 1
                end if
            end if
            if (k > 1) then
                if (abs(f%x(k - 1) - tref) > 0.0_dp) then
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
