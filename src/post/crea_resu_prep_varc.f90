!> CREA_RESU OPERATION='PREP_VARC' with EVOL_THER (U4.44.12; Code_Aster's crvarc and
!> te0408, option PREP_VRC): the temperature in the layers of multilayer plates, from a
!> thermal result "of shells" whose TEMP field holds TEMP_INF, TEMP_MIL, TEMP_SUP. For each
!> DKT/DKQ cell of MODELE (TOUT, or GROUP_MA) at each instant (every stored one, or those
!> of INST / LIST_INST within PRECISION and CRITERE), with h = EPAIS and the cell's means
!> over its nodes of the three values:
!>   T(z) = T_MIL + (T_SUP - T_INF) z / h + 2 (T_INF + T_SUP - 2 T_MIL) z^2 / h^2
!> at the sub-points of its COQUE_NCOU layers (INF, MOY, SUP of each, from the bottom face
!> z = -h/2; the offset EXCENTREMENT plays no part, as in te0408). The result is an
!> EVOL_THER whose TEMP is an ELEM field (TEMP_R, component TEMP) with 3 x COQUE_NCOU
!> sub-points per cell: what AFFE_VARC EVOL gives the plates (assembly_varc).
!> The form with CHAM_GD (functions of INST and EPAIS) is not built.
module crea_resu_prep_varc
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use strings, only: string_t, to_text
    use deck_concept, only: concept_t, concept_display_name
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: cell_label
    use mesh_command_support, only: group_cells
    use model_concept, only: model_concept_t
    use model_types, only: is_plate
    use cara_elem_concept, only: cara_elem_concept_t
    use model_varc, only: cell_temperature_t, field_cell_temperature, TEMP_PROFILE
    use field_types, only: field_t, component_set_t, field_init_cells, field_define_cells, &
        field_position, FIELD_ELEM
    use result_fields, only: result_fields_t, result_fields_init, result_add_instant, &
        result_put_field, result_field_index
    use result_instants, only: selected_instants
    use element_plate_initial_strains, only: plate_layer_points
    implicit none
    private

    public :: run_prep_varc

contains

    !> The PREP_VARC operation of CREA_RESU (module header).
    !>  result : out, an evol_ther
    !>  st     : located errors: CHAM_GD (not built), a CARA_ELEM of another model, an
    !>           EVOL_THER without TEMP_INF / TEMP_MIL / TEMP_SUP on a plate cell, an
    !>           instant not stored
    subroutine run_prep_varc(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(keyword_set_t) :: occ
        type(result_fields_t), allocatable :: made
        class(concept_t), pointer :: pm, pc, pe
        integer(i4), allocatable :: cells(:)
        integer, allocatable :: picked(:)
        logical :: by_inst
        integer(i4) :: k, index, at
        type(field_t) :: f
        occ = cmd%occurrence('PREP_VARC', 1)
        if (occ%has('CHAM_GD')) then
            call occ%error_at('CHAM_GD', 'PREP_VARC from a field of functions (INST, EPAIS) ' &
                // 'is not built; give EVOL_THER', st, code=STATUS_NOT_IMPLEMENTED)
            return
        end if
        call occ%get_concept('MODELE', pm, st)
        if (st%ok()) call occ%get_concept('CARA_ELEM', pc, st)
        if (st%ok()) call occ%get_concept('EVOL_THER', pe, st)
        if (st%failed()) return
        select type (pm)
        type is (model_concept_t)
            select type (pc)
            type is (cara_elem_concept_t)
                select type (pe)
                class is (result_fields_t)
                    call select_cells(occ, pm, cells, st)
                    if (st%ok()) call selected_instants(occ, pe, picked, by_inst, st)
                    if (st%failed()) return
                    allocate (made)
                    call result_fields_init(made, 'evol_ther', size(picked, kind=i4))
                    do k = 1, size(picked)
                        call layers_field(occ, pm, pc, pe, picked(k), cells, f, st)
                        if (st%failed()) return
                        call result_add_instant(made, k, pe%inst(picked(k)), index)
                        call result_put_field(made, index, 'TEMP', f)
                    end do
                class default
                    call occ%error_at('EVOL_THER', 'expected a thermal result, got ' // &
                                      pe%type_name(), st)
                    return
                end select
            class default
                call occ%error_at('CARA_ELEM', 'expected a cara_elem, got ' // &
                                  pc%type_name(), st)
                return
            end select
        class default
            call occ%error_at('MODELE', 'expected a model, got ' // pm%type_name(), st)
            return
        end select
        at = size(picked, kind=i4)
        call ctx%write_mess('    CREA_RESU PREP_VARC: evol_ther, ' // to_text(at) // &
            ' instant(s), the temperature in the layers of ' // &
            to_text(size(cells, kind=i4)) // ' plate cell(s)')
        call move_alloc(made, result)
    end subroutine run_prep_varc

    ! The plate cells of the model among TOUT or GROUP_MA.
    subroutine select_cells(occ, mc, cells, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        integer(i4), allocatable, intent(out) :: cells(:)
        type(status_t), intent(out) :: st
        integer(i4) :: c
        if (occ%has('GROUP_MA')) then
            call group_cells(occ, 'GROUP_MA', mc%mesh, cells, st)
            if (st%failed()) return
        else
            cells = [(c, c = 1, mc%mesh%n_cells)]
        end if
        cells = pack(cells, is_plate(mc%model%element(cells)))
    end subroutine select_cells

    ! The ELEM field of the temperature at the layers' sub-points at stored instant `at`.
    subroutine layers_field(occ, mc, cc, res, at, cells, f, st)
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        type(cara_elem_concept_t), intent(in) :: cc
        class(result_fields_t), intent(in) :: res
        integer(i4), intent(in) :: at, cells(:)
        type(field_t), intent(out) :: f
        type(status_t), intent(out) :: st
        type(cell_temperature_t) :: temp
        type(component_set_t) :: sets(1)
        integer(i4), allocatable :: n_points(:), n_sub(:), cell_set(:)
        real(dp), allocatable :: z(:), w(:)
        real(dp) :: tp(3), h, cp1, cp2, cp3
        integer(i4) :: j, k, c, layers, kf
        kf = result_field_index(res, at, 'TEMP')
        if (kf == 0) then
            call occ%error_at('EVOL_THER', concept_display_name(res) // ' has no TEMP at ' // &
                'INST ' // to_text(res%inst(at)), st, code=STATUS_MODEL_ERROR)
            return
        end if
        call field_init_cells(f, FIELD_ELEM, 'TEMP_R', [string_t('TEMP')], mc%mesh%n_cells, st)
        if (st%failed()) return
        allocate (n_points(mc%mesh%n_cells), n_sub(mc%mesh%n_cells), &
                  cell_set(mc%mesh%n_cells), source=0_i4)
        n_points(cells) = 1
        n_sub(cells) = 3 * cc%cara%coque_layers(cells)
        cell_set(cells) = 1
        sets(1)%cmp = [1_i4]
        call field_define_cells(f, n_points, n_sub, cell_set, sets, st)
        if (st%failed()) return
        do k = 1, size(cells)
            c = cells(k)
            call field_cell_temperature(res%stored(at)%items(kf)%field, mc%mesh, c, temp, st)
            if (st%ok() .and. temp%kind /= TEMP_PROFILE) call set_error(st, &
                STATUS_MODEL_ERROR, 'its TEMP has no TEMP_INF, TEMP_MIL, TEMP_SUP there')
            if (st%failed()) then
                call occ%error_at('EVOL_THER', 'INST ' // to_text(res%inst(at)) // ', ' // &
                    cell_label(mc%mesh, c) // ': ' // st%message, st, code=STATUS_MODEL_ERROR)
                return
            end if
            tp = sum(temp%t, dim=2) / real(temp%nn, dp)            ! INF, MIL, SUP means
            h = cc%cara%thickness(c)
            layers = cc%cara%coque_layers(c)
            if (allocated(z)) deallocate (z, w)
            allocate (z(3 * layers), w(3 * layers))
            call plate_layer_points(h, layers, z, w)
            cp1 = tp(2)
            cp2 = (tp(3) - tp(1)) / h
            cp3 = 2.0_dp * (tp(1) + tp(3) - 2.0_dp * tp(2)) / (h * h)
            do j = 1, 3 * layers
                f%values(field_position(f, c, 1_i4, j, 1_i4)) = cp1 + cp2 * z(j) + cp3 * z(j)**2
            end do
        end do
    end subroutine layers_field

end module crea_resu_prep_varc
