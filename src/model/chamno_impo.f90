!> AFFE_CHAR_MECA CHAMNO_IMPO (Code_Aster U4.44.01, caimch): every component DX .. DRZ a
!> nodal displacement field (CHAM_NO, a NOEU_DEPL_R of CREA_CHAMP or PROJ_CHAMP) holds at a
!> node is imposed, u = COEF_IMPO x value. Code_Aster writes one single-term relation per
!> value (dualised); parasol imposes them as DDL_IMPO values (eliminated), the same
!> equations and the same REAC_NODA.
module chamno_impo
    use kinds, only: dp, i4
    use status, only: status_t, STATUS_MODEL_ERROR
    use strings, only: to_text
    use deck_concept, only: concept_t
    use deck_command, only: keyword_set_t
    use mesh_types, only: node_name
    use model_dof_numbering, only: COMPONENT_NAMES, N_COMPONENTS
    use model_concept, only: model_concept_t
    use model_loads, only: load_set_t, load_add_item, load_set_constant, load_set_location, &
        LOAD_DDL_IMPO
    use field_types, only: FIELD_NOEU, field_component
    use field_concept, only: field_concept_t
    implicit none
    private

    public :: chamno_impo_item

contains

    !> One CHAMNO_IMPO occurrence: a DDL_IMPO item per node the field holds values at.
    !>  st : out, located: CHAM_NO not a nodal displacement field, a field on another mesh,
    !>       a value on a component the node has not in the model
    subroutine chamno_impo_item(occ, mc, loads, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        real(dp) :: coef
        integer(i4) :: kcomp(N_COMPONENTS), c, n, index
        character(len=:), allocatable :: file
        integer :: line, col
        call occ%get_real('COEF_IMPO', coef, st)
        if (st%ok()) call occ%get_concept('CHAM_NO', p, st)
        if (st%failed()) return
        select type (p)
        type is (field_concept_t)
            if (p%field%location /= FIELD_NOEU .or. p%field%quantity /= 'DEPL_R') then
                call occ%error_at('CHAM_NO', 'CHAMNO_IMPO imposes a nodal displacement ' // &
                    'field (NOEU_DEPL_R); this one is not (Code_Aster MODELISA2_85)', st, &
                    code=STATUS_MODEL_ERROR)
                return
            end if
            if (p%field%n_nodes /= mc%mesh%n_nodes) then
                call occ%error_at('CHAM_NO', 'the field has ' // to_text(p%field%n_nodes) // &
                    ' nodes, the model''s mesh ' // to_text(mc%mesh%n_nodes) // ': a field ' // &
                    'of another mesh', st, code=STATUS_MODEL_ERROR)
                return
            end if
            do c = 1, N_COMPONENTS
                kcomp(c) = field_component(p%field, trim(COMPONENT_NAMES(c)))
            end do
            call occ%location('', file, line, col)
            do n = 1, p%field%n_nodes
                if (.not. any(kcomp > 0)) exit
                if (.not. any(p%field%node_has(pack(kcomp, kcomp > 0), n))) cycle
                call load_add_item(loads, LOAD_DDL_IMPO, [n], index, 'CHAMNO_IMPO')
                call load_set_location(loads, index, file, line, col, occ%command, occ%scope)
                do c = 1, N_COMPONENTS
                    if (kcomp(c) == 0) cycle
                    if (.not. p%field%node_has(kcomp(c), n)) cycle
                    if (mc%dofs%equation(c, n) <= 0) then
                        call occ%error_at('CHAM_NO', 'the field gives node ' // &
                            node_name(mc%mesh, n) // ' a value of ' // &
                            trim(COMPONENT_NAMES(c)) // ', which it has not in the model', &
                            st, code=STATUS_MODEL_ERROR)
                        return
                    end if
                    call load_set_constant(loads, index, c, &
                        coef * p%field%node_values(kcomp(c), n))
                end do
            end do
        class default
            call occ%error_at('CHAM_NO', 'expected a nodal field (cham_no_sdaster), got ' // &
                p%type_name(), st, code=STATUS_MODEL_ERROR)
        end select
    end subroutine chamno_impo_item

end module chamno_impo
