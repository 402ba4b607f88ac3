!> The 'maillage' concept: the result of LIRE_MAILLAGE, a mesh read from a file.
!> Later commands (AFFE_MODELE, AFFE_MATERIAU, ...) reach the mesh through `%mesh`.
module mesh_concept
    use deck_concept, only: concept_t, concept_display_name
    use mesh_types, only: mesh_t, mesh_release
    use strings, only: to_text
    implicit none
    private

    !> A mesh read by LIRE_MAILLAGE.
    !>
    !> Its final procedure frees the mesh explicitly. Without it, every run leaked the cell
    !> name index (mesh%cell_names: its pool, starts and hash table) when the run context
    !> freed its concepts: the finalization wrapper gfortran 12.2 generates for this type
    !> (called by `deallocate` of the class(concept_t) box that owns it) frees every
    !> allocatable component of mesh_t but that second name_index_t one. The omission is in
    !> the front end (-fdump-tree-original of this file shows no deallocation of
    !> mesh%cell_names in __final_mesh_concept_Mesh_concept_t, compiled with -std=f2018 as
    !> the project is, or without it once the module is cut down) and comes and goes with
    !> unrelated details (the order of the use statements, a component added after the
    !> mesh), so it is not worked around by rearranging them; a type(mesh_t) deallocated
    !> directly, and the model and material concepts that hold a copy of the mesh, are freed
    !> completely. Found by valgrind (CTest valgrind.*).
    type, extends(concept_t), public :: mesh_concept_t
        type(mesh_t) :: mesh   !< nodes, cells, groups, as read (mesh%file names the file)
    contains
        procedure :: type_name => mesh_concept_type_name
        procedure :: summary => mesh_concept_summary
        final :: mesh_concept_final
    end type mesh_concept_t

contains

    !> Frees the mesh (see the type's comment: a compiler omission, not a design need).
    subroutine mesh_concept_final(self)
        type(mesh_concept_t), intent(inout) :: self
        call mesh_release(self%mesh)
    end subroutine mesh_concept_final

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
