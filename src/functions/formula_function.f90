!> FORMULE: a function given by an expression of named parameters (NOM_PARA), compiled once
!> to bytecode (formula_program) and evaluated through the function_concept API.
module formula_function
    use kinds, only: dp
    use strings, only: string_t, to_text
    use status, only: status_t
    use deck_concept, only: concept_display_name
    use function_concept, only: function_concept_t, param_binding_t, missing_parameter
    use formula_program, only: program_t, run_program
    implicit none
    private

    type, extends(function_concept_t), public :: formula_function_t
        type(string_t), allocatable :: params(:)     !< NOM_PARA, in order
        character(len=:), allocatable :: source      !< the VALE text
        type(program_t) :: prog
    contains
        procedure :: type_name => formula_type_name
        procedure :: parameters => formula_parameters
        procedure :: evaluate => formula_evaluate
        procedure :: summary => formula_summary
    end type formula_function_t

contains

    function formula_type_name(self) result(name)
        class(formula_function_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'formule'
        if (.false.) name = self%source
    end function formula_type_name

    function formula_parameters(self) result(names)
        class(formula_function_t), intent(in) :: self
        type(string_t), allocatable :: names(:)
        names = self%params
    end function formula_parameters

    !> Runs the compiled VALE; every NOM_PARA must be bound by the caller.
    recursive subroutine formula_evaluate(self, binding, values, y, st)
        class(formula_function_t), intent(in) :: self
        type(param_binding_t), intent(in) :: binding
        real(dp), intent(in) :: values(:)
        real(dp), intent(out) :: y
        type(status_t), intent(out) :: st
        integer :: k
        y = 0.0_dp
        do k = 1, size(binding%slot)
            if (binding%slot(k) == 0) then
                call missing_parameter(concept_display_name(self), binding, k, st)
                return
            end if
        end do
        call run_program(self%prog, binding%slot, values, y, st)
        if (st%failed()) then
            st%message = 'FORMULE ' // concept_display_name(self) // ': ' // st%message // &
                         ' (at'
            do k = 1, size(binding%slot)
                st%message = st%message // ' ' // self%params(k)%s // ' = ' // &
                             to_text(values(binding%slot(k)))
            end do
            st%message = st%message // ')'
        end if
    end subroutine formula_evaluate

    function formula_summary(self) result(text)
        class(formula_function_t), intent(in) :: self
        character(len=:), allocatable :: text
        integer :: k
        text = concept_display_name(self) // ' (formule) of ('
        do k = 1, size(self%params)
            if (k > 1) text = text // ', '
            text = text // self%params(k)%s
        end do
        text = text // ') = ' // one_line(self%source)
        if (len(text) > 100) text = text(1:97) // '...'
    end function formula_summary

    !> The text on one line: line ends and runs of blanks become one blank.
    pure function one_line(text) result(out)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: out
        integer :: i
        character :: c
        out = ''
        do i = 1, len(text)
            c = text(i:i)
            if (c == achar(10) .or. c == achar(13) .or. c == achar(9)) c = ' '
            if (c == ' ' .and. len(out) > 0) then
                if (out(len(out):len(out)) == ' ') cycle
            end if
            out = out // c
        end do
    end function one_line

end module formula_function
