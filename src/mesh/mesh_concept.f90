!> The 'maillage' concept: the result of LIRE_MAILLAGE, a mesh read from a file.
!> Later commands (AFFE_MODELE, AFFE_MATERIAU, ...) reach the mesh through `%mesh`.
module mesh_concept
    use deck_concept, only: concept_t, concept_display_name
    use mesh_types, only: mesh_t
    use strings, only: to_text
    implicit none
    private

    !> A mesh read by LIRE_MAILLAGE.
    type, extends(concept_t), public :: mesh_concept_t
        type(mesh_t) :: mesh   !< nodes, cells, groups, as read (mesh%file names the file)
    contains
        procedure :: type_name => mesh_concept_type_name
        procedure :: summary => mesh_concept_summary
    end type mesh_concept_t

contains

    function mesh_concept_type_name(self) result(name)
        class(mesh_concept_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'maillage'
        if (.false.) name = self%name
    end function mesh_concept_type_name

    !> "MESH (maillage): 12 nodes, 10 cells, 3 groups of cells, from mesh.mail".
    function mesh_concept_summary(self) result(text)
        class(mesh_concept_t), intent(in) :: self
        character(len=:), allocatable :: text
        text = concept_display_name(self) // ' (maillage): ' // to_text(self%mesh%n_nodes) // &
            ' nodes, ' // to_text(self%mesh%n_cells) // ' cells, ' // &
            to_text(self%mesh%cell_group_names%count) // ' cell groups, ' // &
            to_text(self%mesh%node_group_names%count) // ' node groups'
        if (allocated(self%mesh%file)) text = text // ', from ' // self%mesh%file
    end function mesh_concept_summary

end module mesh_concept
