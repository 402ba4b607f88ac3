!> DEFI_LIST_REEL: a strictly increasing list of reals (time lists of the analyses).
module real_list
    use kinds, only: dp
    use strings, only: to_text
    use deck_concept, only: concept_t, concept_display_name
    implicit none
    private

    type, extends(concept_t), public :: real_list_t
        real(dp), allocatable :: values(:)
    contains
        procedure :: type_name => list_type_name
        procedure :: summary => list_summary
    end type real_list_t

contains

    function list_type_name(self) result(name)
        class(real_list_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'listr8'
        if (.false.) name = self%name
    end function list_type_name

    function list_summary(self) result(text)
        class(real_list_t), intent(in) :: self
        character(len=:), allocatable :: text
        text = concept_display_name(self) // ' (listr8): ' // to_text(size(self%values)) // &
            ' values'
        if (size(self%values) > 0) text = text // ' from ' // to_text(self%values(1)) // &
            ' to ' // to_text(self%values(size(self%values)))
    end function list_summary

end module real_list
