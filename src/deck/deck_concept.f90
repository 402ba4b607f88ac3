!> The base type of every deck concept (the results of commands: mesh, model, material,
!> function, result...). Later layers extend `concept_t`; the deck layer only needs the
!> deck name, the catalog type name (for type checks) and a one-line summary for the .mess.
module deck_concept
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_DECK_ERROR
    implicit none
    private

    !> A concept produced by a command. Extend it and implement `type_name`, returning the
    !> catalog type of the producing command (e.g. 'maillage', 'fonction', 'evol_noli').
    type, abstract, public :: concept_t
        character(len=:), allocatable :: name   !< deck variable name ('' while unnamed)
    contains
        procedure(concept_type_name), deferred :: type_name
        procedure :: summary => concept_summary
        procedure :: call_real => concept_call_real
    end type concept_t

    abstract interface
        !> The catalog type name of the concept.
        function concept_type_name(self) result(name)
            import :: concept_t
            class(concept_t), intent(in) :: self
            character(len=:), allocatable :: name
        end function concept_type_name
    end interface

    !> What the check pass (parasol --check) produces in place of a real concept: it has the
    !> catalog result type of its command, so later references type-check.
    type, extends(concept_t), public :: placeholder_concept_t
        character(len=:), allocatable :: kind_name
    contains
        procedure :: type_name => placeholder_type_name
    end type placeholder_concept_t

    public :: concept_display_name

contains

    !> Calls the concept from the deck with real arguments, `F(1.0)`; concepts that are
    !> functions override this (the deck layer does not know them). Default: an error.
    !>  args : in, the arguments;  y : out, the value;  st : out, why it cannot be called
    recursive subroutine concept_call_real(self, args, y, st)
        class(concept_t), intent(in) :: self
        real(dp), intent(in) :: args(:)
        real(dp), intent(out) :: y
        type(status_t), intent(out) :: st
        y = 0.0_dp
        if (size(args) < 0) return
        call set_error(st, STATUS_DECK_ERROR, 'a concept of type ' // self%type_name() // &
                       ' cannot be called')
    end subroutine concept_call_real

    !> One-line description for the .mess; extensions override it with counts etc.
    function concept_summary(self) result(text)
        class(concept_t), intent(in) :: self
        character(len=:), allocatable :: text
        text = concept_display_name(self) // ' (' // self%type_name() // ')'
    end function concept_summary

    !> The deck name, or '(unnamed)' for a concept used directly inside an expression.
    function concept_display_name(c) result(text)
        class(concept_t), intent(in) :: c
        character(len=:), allocatable :: text
        text = '(unnamed)'
        if (allocated(c%name)) then
            if (len(c%name) > 0) text = c%name
        end if
    end function concept_display_name

    function placeholder_type_name(self) result(name)
        class(placeholder_concept_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'unknown'
        if (allocated(self%kind_name)) name = self%kind_name
    end function placeholder_type_name

end module deck_concept
