!> The 'mater' concept (DEFI_MATERIAU: one material) and the 'cham_mater' concept
!> (AFFE_MATERIAU: which material each cell of a mesh has).
module material_concept
    use kinds, only: i4
    use deck_concept, only: concept_t, concept_display_name
    use mesh_types, only: mesh_t, mesh_release
    use model_material, only: material_t, material_field_t, behaviour_names
    use strings, only: to_text
    implicit none
    private

    !> A material defined by DEFI_MATERIAU.
    type, extends(concept_t), public :: material_concept_t
        type(material_t) :: material   !< its behaviours (ELAS, DIS_CONTACT decoded)
    contains
        procedure :: type_name => material_type_name
        procedure :: summary => material_summary
    end type material_concept_t

    !> A material field defined by AFFE_MATERIAU.
    !> Its final procedure frees the mesh explicitly: gfortran 12.2's finalization wrapper
    !> for this type left the mesh copy's name indices allocated once material_t held its
    !> behaviours (valgrind; the compiler omission mesh_concept_t describes).
    type, extends(concept_t), public :: material_field_concept_t
        type(mesh_t) :: mesh               !< copy of the mesh the field applies to
        type(material_field_t) :: field    !< field%materials(field%cell_material(c)), 0 = none
    contains
        procedure :: type_name => material_field_type_name
        procedure :: summary => material_field_summary
        final :: material_field_final
    end type material_field_concept_t

contains

    !> Frees the mesh copy (see the type's comment: a compiler omission).
    subroutine material_field_final(self)
        type(material_field_concept_t), intent(inout) :: self
        call mesh_release(self%mesh)
    end subroutine material_field_final

    function material_type_name(self) result(name)
        class(material_concept_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'mater'
        if (.false.) name = self%name
    end function material_type_name

    !> "STEEL (mater): ELAS DIS_CONTACT" (its behaviours, in the order given).
    function material_summary(self) result(text)
        class(material_concept_t), intent(in) :: self
        character(len=:), allocatable :: text
        text = concept_display_name(self) // ' (mater): ' // behaviour_names(self%material)
    end function material_summary

    function material_field_type_name(self) result(name)
        class(material_field_concept_t), intent(in) :: self
        character(len=:), allocatable :: name
        name = 'cham_mater'
        if (.false.) name = self%name
    end function material_field_type_name

    !> "CHMAT (cham_mater): 2 materials on 40 cells".
    function material_field_summary(self) result(text)
        class(material_field_concept_t), intent(in) :: self
        character(len=:), allocatable :: text
        integer(i4) :: n_mat, n_cells
        n_mat = 0
        n_cells = 0
        if (allocated(self%field%materials)) n_mat = size(self%field%materials)
        if (allocated(self%field%cell_material)) &
            n_cells = count(self%field%cell_material > 0, kind=i4)
        text = concept_display_name(self) // ' (cham_mater): ' // to_text(n_mat) // &
            ' materials on ' // to_text(n_cells) // ' cells'
    end function material_field_summary

end module material_concept
