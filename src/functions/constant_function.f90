!> DEFI_CONSTANTE: a function that returns the same value for any parameters.
module constant_function
    use kinds, only: dp
    use strings, only: string_t, to_text
    use status, only: status_t
    use deck_concept, only: concept_display_name
    use function_concept, only: function_concept_t, param_binding_t
    implicit none
    private

    type, extends(function_concept_t), public :: constant_function_t
        real(dp) :: value = 0.0_dp
        character(len=:), allocatable :: result_name      !< NOM_RESU (default TOUTRESU)
    contains
        procedure :: type_name => constant_type_name
        procedure :: parameters => constant_parameters
        procedure :: evaluate => constant_evaluate
        procedure :: summary => constant_summary
    end type constant_function_t

contains

    function constant_type_name(self) result(name)
        class(constant_function_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'fonction'
        if (.false.) name = self%name
    end function constant_type_name

    !> No parameter: any caller binding works.
    function constant_parameters(self) result(names)
        class(constant_function_t), intent(in) :: self
        type(string_t), allocatable :: names(:)
        allocate (names(0))
        if (.false.) names(1)%s = self%name
    end function constant_parameters

    subroutine constant_evaluate(self, binding, values, y, st)
        class(constant_function_t), intent(in) :: self
        type(param_binding_t), intent(in) :: binding
        real(dp), intent(in) :: values(:)
        real(dp), intent(out) :: y
        type(status_t), intent(out) :: st
        y = self%value
        if (.false.) y = values(size(binding%slot))
        if (st%failed()) return
    end subroutine constant_evaluate

    function constant_summary(self) result(text)
        class(constant_function_t), intent(in) :: self
        character(len=:), allocatable :: text
        text = concept_display_name(self) // ' (fonction): constant ' // to_text(self%value)
    end function constant_summary

end module constant_function
