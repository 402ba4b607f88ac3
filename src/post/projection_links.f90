!> LIAISON_PROJ's view of PROJ_CHAMP's correspondence (relation_proj's node_links_t): the
!> meshes of its two sides and, per target node, the source cell and its nodes' weights.
!> The composition root hands links_of_projection to relation_proj (module header there).
module projection_links
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use deck_concept, only: concept_t
    use mesh_types, only: mesh_t
    use mesh_concept, only: mesh_concept_t
    use model_concept, only: model_concept_t
    use relation_proj, only: node_links_t
    use projection_concept, only: projection_concept_t
    implicit none
    private

    public :: links_of_projection

contains

    !> The links of a corresp_2_mailla concept (relation_proj's links_of_f).
    subroutine links_of_projection(concept, links, st)
        class(concept_t), pointer, intent(in) :: concept
        type(node_links_t), intent(out) :: links
        type(status_t), intent(out) :: st
        select type (concept)
        type is (projection_concept_t)
            links%source => mesh_of_side(concept%source)
            links%target => mesh_of_side(concept%target)
            if (.not. allocated(concept%proj%cell)) then
                call set_error(st, STATUS_MODEL_ERROR, 'the correspondence holds no projection')
                return
            end if
            links%cell = concept%proj%cell
            where (.not. concept%proj%projected) links%cell = 0
            links%weights = concept%proj%weights
        class default
            call set_error(st, STATUS_MODEL_ERROR, 'expected a corresp_2_mailla (PROJ_CHAMP ' // &
                'with PROJECTION=''NON''), got ' // concept%type_name())
        end select
    end subroutine links_of_projection

    ! The mesh of a side of the projection (MAILLAGE_x, MODELE_x); null when unknown.
    function mesh_of_side(side) result(mesh)
        class(concept_t), pointer, intent(in) :: side
        type(mesh_t), pointer :: mesh
        mesh => null()
        if (.not. associated(side)) return
        select type (side)
        type is (mesh_concept_t)
            mesh => side%mesh
        type is (model_concept_t)
            mesh => side%mesh
        end select
    end function mesh_of_side

end module projection_links
