!> The 'cara_elem' concept: the result of AFFE_CARA_ELEM (shell thickness, discrete
!> stiffnesses, orientations per cell, and the RIGI_PARASOL tables that produced some of
!> the discrete stiffnesses, kept for the listing and for checks).
module cara_elem_concept
    use kinds, only: i4
    use deck_concept, only: concept_t, concept_display_name
    use model_cara_elem, only: cara_elem_t, CARA_NONE
    use model_rigi_parasol, only: rigi_parasol_table_t
    use strings, only: to_text
    implicit none
    private

    !> Element characteristics of a model.
    type, extends(concept_t), public :: cara_elem_concept_t
        type(cara_elem_t) :: cara     !< per-cell COQUE / DISCRET / ORIENTATION data
        integer(i4) :: n_parasol = 0      !< number of RIGI_PARASOL occurrences
        !> (n_parasol) the table of each RIGI_PARASOL occurrence (already applied to cara)
        type(rigi_parasol_table_t), allocatable :: parasol(:)
    contains
        procedure :: type_name => cara_elem_type_name
        procedure :: summary => cara_elem_summary
    end type cara_elem_concept_t

contains

    function cara_elem_type_name(self) result(name)
        class(cara_elem_concept_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'cara_elem'
        if (.false.) name = self%name
    end function cara_elem_type_name

    !> "CARA (cara_elem): 40 shells, 51 discretes, 1 RIGI_PARASOL".
    function cara_elem_summary(self) result(text)
        class(cara_elem_concept_t), intent(in) :: self
        character(len=:), allocatable :: text
        integer(i4) :: n_shell, n_disc
        n_shell = 0
        n_disc = 0
        if (allocated(self%cara%has_coque)) n_shell = count(self%cara%has_coque, kind=i4)
        if (allocated(self%cara%discrete_cara)) &
            n_disc = count(self%cara%discrete_cara /= CARA_NONE, kind=i4)
        text = concept_display_name(self) // ' (cara_elem): ' // to_text(n_shell) // &
            ' shells, ' // to_text(n_disc) // ' discretes, ' // to_text(self%n_parasol) // &
            ' RIGI_PARASOL'
    end function cara_elem_summary

end module cara_elem_concept
