!> The 'corresp_2_mailla' concept: what PROJ_CHAMP(PROJECTION='NON') computes, the
!> correspondence of the nodes of a target mesh to the cells of a source mesh (the cell
!> and the weights of its nodes for each target node, field_projection's projection_t).
!> PROJ_CHAMP(MATR_PROJECTION=...) projects fields with it; Code_Aster's
!> AFFE_CHAR_MECA(LIAISON_PROJ) reads the same relations.
module projection_concept
    use deck_concept, only: concept_t, concept_display_name
    use strings, only: to_text
    use field_projection, only: projection_t
    implicit none
    private

    type, extends(concept_t), public :: projection_concept_t
        type(projection_t) :: proj
        class(concept_t), pointer :: source => null()   !< MODELE_1 or MAILLAGE_1
        class(concept_t), pointer :: target => null()   !< MODELE_2 or MAILLAGE_2
    contains
        procedure :: type_name => projection_type_name
        procedure :: summary => projection_summary
    end type projection_concept_t

contains

    function projection_type_name(self) result(name)
        class(projection_concept_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'corresp_2_mailla'
        if (.false.) name = self%name
    end function projection_type_name

    !> "P (corresp_2_mailla): 12 nodes projected".
    function projection_summary(self) result(text)
        class(projection_concept_t), intent(in) :: self
        character(len=:), allocatable :: text
        integer :: n
        n = 0
        if (allocated(self%proj%projected)) n = count(self%proj%projected)
        text = concept_display_name(self) // ' (corresp_2_mailla): ' // to_text(n) // &
            ' nodes projected'
    end function projection_summary

end module projection_concept
