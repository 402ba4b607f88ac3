!> The mesh and the model a field or a command refers to, from the concept given
!> (doc/architecture.md, "Fields and results"): a maillage's mesh, a modele's copy of the
!> mesh and its elements, or a result's mesh and model.
module field_support
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use deck_concept, only: concept_t
    use mesh_types, only: mesh_t
    use mesh_concept, only: mesh_concept_t
    use model_types, only: model_t
    use model_concept, only: model_concept_t
    use analysis_result, only: result_concept_t
    implicit none
    private

    public :: mesh_of_support, model_of_support

contains

    !> The mesh of `support` (maillage, modele or result).
    !>  st : STATUS_MODEL_ERROR when the concept is none of these
    subroutine mesh_of_support(support, mesh, st)
        class(concept_t), pointer, intent(in) :: support
        type(mesh_t), pointer, intent(out) :: mesh
        type(status_t), intent(out) :: st
        mesh => null()
        if (.not. associated(support)) then
            call set_error(st, STATUS_MODEL_ERROR, 'the field knows no mesh')
            return
        end if
        select type (support)
        type is (mesh_concept_t)
            mesh => support%mesh
        type is (model_concept_t)
            mesh => support%mesh
        type is (result_concept_t)
            mesh => support%mesh
        class default
            call set_error(st, STATUS_MODEL_ERROR, 'expected a mesh (maillage), a model ' // &
                '(modele) or a result, got ' // support%type_name())
        end select
    end subroutine mesh_of_support

    !> The model (the element of each cell) of `support` (modele, or a result of an
    !> analysis); null for a maillage or a result that knows none.
    subroutine model_of_support(support, model)
        class(concept_t), pointer, intent(in) :: support
        type(model_t), pointer, intent(out) :: model
        model => null()
        if (.not. associated(support)) return
        select type (support)
        type is (model_concept_t)
            model => support%model
        type is (result_concept_t)
            if (support%has_structure) model => support%model
        end select
    end subroutine model_of_support

end module field_support
