!> The 'modele' concept: the result of AFFE_MODELE. It refers to the mesh of MAILLAGE (so
!> later commands need only the model), and carries the element kind of every cell and the
!> DOF numbering of the nodes those elements touch.
!>
!> The mesh is referred to, not copied, as in Code_Aster: the mesh commands that modify a
!> mesh in place (DEFI_GROUP's new groups, MODI_MAILLAGE's orientations and moves, reuse=)
!> after AFFE_MODELE are seen by every later command through the model. They keep the
!> numbers of nodes and cells, so the element kinds and the DOF numbering stay valid. The
!> mesh concept is owned by the run context, whose concepts never move and live until the
!> end of the run.
module model_concept
    use deck_concept, only: concept_t, concept_display_name
    use mesh_types, only: mesh_t
    use model_types, only: model_t, n_modelled_cells
    use model_dof_numbering, only: dof_numbering_t
    use strings, only: to_text
    implicit none
    private

    !> A finite-element model: mesh + element per cell + DOF numbering.
    type, extends(concept_t), public :: model_concept_t
        type(mesh_t), pointer :: mesh => null()   !< the MAILLAGE mesh (not owned)
        type(model_t) :: model            !< model%element(c): ELEM_* of cell c (ELEM_NONE: none)
        type(dof_numbering_t) :: dofs     !< equation numbers of (component, node)
    contains
        procedure :: type_name => model_concept_type_name
        procedure :: summary => model_concept_summary
    end type model_concept_t

contains

    function model_concept_type_name(self) result(name)
        class(model_concept_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'modele'
        if (.false.) name = self%name
    end function model_concept_type_name

    !> "MODEL (modele): 40 elements, 765 equations".
    function model_concept_summary(self) result(text)
        class(model_concept_t), intent(in) :: self
        character(len=:), allocatable :: text
        text = concept_display_name(self) // ' (modele): ' // &
            to_text(n_modelled_cells(self%model)) // ' elements, ' // &
            to_text(self%dofs%n_equations) // ' equations'
    end function model_concept_summary

end module model_concept
