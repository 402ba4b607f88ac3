!> The function concept DEFI_PRES_EC8 makes: the EC8 tank pressure (ec8_tank_pressure) as a
!> function of X, Y, Z, EP, RHO, the parameters of Code_Aster's formula (its sd_prod is a
!> formule). FORCE_COQUE_FO evaluates it with the cell's centre, the shell's EPAIS and the
!> material's ELAS RHO; a deck may call it as fonc(x, y, z, ep, rho).
module ec8_pressure_function
    use kinds, only: dp
    use strings, only: string_t, to_text
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use deck_concept, only: concept_display_name
    use function_concept, only: function_concept_t, param_binding_t, missing_parameter
    use ec8_tank_pressure, only: ec8_tank_t, ec8_parts_t, ec8_pressure
    implicit none
    private

    !> NOM_PARA of the formula, in call order (Code_Aster defi_pres_ec8_ops).
    character(len=3), parameter, public :: EC8_PARAMETER_NAMES(5) = ['X  ', 'Y  ', 'Z  ', 'EP ', &
        'RHO']

    type, extends(function_concept_t), public :: ec8_pressure_function_t
        type(ec8_tank_t) :: tank
    contains
        procedure :: type_name => ec8_type_name
        procedure :: parameters => ec8_parameters
        procedure :: evaluate => ec8_evaluate
        procedure :: summary => ec8_summary
    end type ec8_pressure_function_t

contains

    function ec8_type_name(self) result(name)
        class(ec8_pressure_function_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'formule'
        if (.false.) name = self%name
    end function ec8_type_name

    function ec8_parameters(self) result(names)
        class(ec8_pressure_function_t), intent(in) :: self
        type(string_t), allocatable :: names(:)
        integer :: k
        allocate (names(size(EC8_PARAMETER_NAMES)))
        do k = 1, size(EC8_PARAMETER_NAMES)
            names(k)%s = trim(EC8_PARAMETER_NAMES(k))
        end do
        if (.false.) names(1)%s = self%name
    end function ec8_parameters

    !> The pressure at the bound (X, Y, Z, EP, RHO); all five must be provided.
    !>  st : a parameter not provided; the point or the shell refused by ec8_pressure
    subroutine ec8_evaluate(self, binding, values, y, st)
        class(ec8_pressure_function_t), intent(in) :: self
        type(param_binding_t), intent(in) :: binding
        real(dp), intent(in) :: values(:)
        real(dp), intent(out) :: y
        type(status_t), intent(out) :: st
        real(dp) :: v(size(EC8_PARAMETER_NAMES))
        type(ec8_parts_t) :: parts
        integer :: k
        y = 0.0_dp
        do k = 1, size(binding%slot)
            if (binding%slot(k) == 0) then
                call missing_parameter(concept_display_name(self), binding, k, st)
                st%message = st%message // ' (DEFI_PRES_EC8 needs the shell''s EP and the ' &
                    // 'material''s RHO: give CARA_ELEM and CHAM_MATER to AFFE_CHAR_MECA)'
                return
            end if
            v(k) = values(binding%slot(k))
        end do
        call ec8_pressure(self%tank, v(1), v(2), v(3), v(4), v(5), parts, st)
        if (st%failed()) then
            call set_error(st, STATUS_MODEL_ERROR, 'DEFI_PRES_EC8 ' // &
                concept_display_name(self) // ': ' // st%message // ' (at X = ' // &
                to_text(v(1)) // ', Y = ' // to_text(v(2)) // ', Z = ' // to_text(v(3)) // ')')
            return
        end if
        y = parts%total
    end subroutine ec8_evaluate

    function ec8_summary(self) result(text)
        class(ec8_pressure_function_t), intent(in) :: self
        character(len=:), allocatable :: text
        text = concept_display_name(self) // ' (formule) of (X, Y, Z, EP, RHO) = ' // &
            'DEFI_PRES_EC8 tank pressure, RAYON ' // to_text(self%tank%radius) // &
            ', HAUT_EAU ' // to_text(self%tank%height)
    end function ec8_summary

end module ec8_pressure_function
