!> POST_CHAMP (Code_Aster U4.81.05, code_aster/Cata/Commands/post_champ.py), EXTR_COQUE: a
!> new result of RESULTAT's type holding, at the instants asked for (TOUT_ORDRE /
!> NUME_ORDRE / INST / LIST_INST, default every one), the fields NOM_CHAM reduced to one
!> sub-point: level NIVE_COUCHE (INF, MOY, SUP) of layer NUME_COUCHE of every plate cell
!> (sub-point 3 (NUME_COUCHE - 1) + 1, 2 or 3, field_types). Cells without sub-points keep
!> their values; TOUT / GROUP_MA restrict the cells. The fields are taken as the result
!> stores them (CALC_CHAMP first), or made from its state (SIEF_ELGA). A layer beyond a
!> cell's COQUE_NCOU is an error naming the cell and its layers. EXTR_TUYAU, EXTR_PMF,
!> MIN_MAX_SP and COQU_EXCENT are refused as not built.
module post_champ_command
    use keyword_relocation, only: relocate => relocate_error
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, &
        STATUS_NOT_IMPLEMENTED
    use strings, only: string_t, to_text
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: cell_label, find_cell_group, cells_of_group
    use real_list, only: real_list_t
    use field_types, only: field_t, field_init_cells, field_define_cells, field_is_cell_field
    use result_fields, only: result_fields_t, result_fields_init, result_add_instant, &
        result_put_field, result_find
    use analysis_result, only: result_concept_t
    use result_access, only: result_field_at
    implicit none
    private

    public :: run_post_champ, extract_subpoint, empty_like

contains

    !> Handler of POST_CHAMP.
    !>  st : located errors (a field not computed, a layer beyond COQUE_NCOU, an instant not
    !>       stored, an extraction not built)
    subroutine run_post_champ(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        type(result_concept_t), allocatable :: out
        type(keyword_set_t) :: occ
        type(string_t), allocatable :: names(:)
        character(len=:), allocatable :: level, other
        integer(i4), allocatable :: indices(:)
        logical, allocatable :: cells(:)
        integer(i4) :: layer, subpoint_in_layer, i, k, at
        type(field_t), pointer :: f
        type(field_t) :: reduced
        other = ''
        if (cmd%count('EXTR_TUYAU') > 0) other = 'EXTR_TUYAU'
        if (cmd%count('EXTR_PMF') > 0) other = 'EXTR_PMF'
        if (cmd%count('MIN_MAX_SP') > 0) other = 'MIN_MAX_SP'
        if (cmd%count('COQU_EXCENT') > 0) other = 'COQU_EXCENT'
        if (len(other) > 0) then
            call cmd%error_at(other, other // ' is not built in parasol (EXTR_COQUE is)', st, &
                STATUS_NOT_IMPLEMENTED)
            return
        end if
        call cmd%get_concept('RESULTAT', p, st)
        if (st%failed()) return
        select type (p)
        type is (result_concept_t)
            occ = cmd%occurrence('EXTR_COQUE', 1)
            call occ%get_texts('NOM_CHAM', names, st)
            if (st%ok()) call occ%get_int('NUME_COUCHE', layer, st)
            if (st%ok()) call occ%get_text('NIVE_COUCHE', level, st)
            if (st%ok()) call post_instants(cmd, p, indices, st)
            if (st%ok()) call post_cells(cmd, p, cells, st)
            if (st%failed()) return
            subpoint_in_layer = index('INF MOY SUP', level) / 4 + 1
            allocate (out)
            call empty_like(p, out)
            do i = 1, size(indices)
                call result_add_instant(out, p%nume_ordre(indices(i)), p%inst(indices(i)), at)
                do k = 1, size(names)
                    call result_field_at(p, indices(i), names(k)%s, f, st)
                    if (st%ok()) call extract_subpoint(f, layer, subpoint_in_layer, cells, &
                        reduced, st)
                    if (st%failed()) then
                        if (index(st%message, 'cell ') == 1) st%message = cell_label(p%mesh, &
                            bad_cell(st%message)) // st%message(index(st%message, ':'):)
                        call relocate(occ, merge('NUME_COUCHE', 'NOM_CHAM   ', &
                            index(st%message, 'layer') > 0), st)
                        return
                    end if
                    call result_put_field(out, at, names(k)%s, reduced)
                end do
            end do
            call ctx%write_mess('    POST_CHAMP EXTR_COQUE: layer ' // to_text(layer) // ' ' // &
                level // ', ' // to_text(size(names)) // ' field(s) at ' // &
                to_text(size(indices)) // ' instant(s)')
            call move_alloc(out, result)
        class default
            call cmd%error_at('RESULTAT', 'expected a result of MECA_STATIQUE or ' // &
                'STAT_NON_LINE, got ' // p%type_name(), st)
        end select
    end subroutine run_post_champ

    !> The number of the cell an extract_subpoint message starts with ('cell 12: ...').
    pure integer(i4) function bad_cell(message) result(c)
        character(len=*), intent(in) :: message
        integer :: colon, ios
        c = 1
        colon = index(message, ':')
        if (colon < 6) return
        read (message(6:colon - 1), *, iostat=ios) c
        if (ios /= 0) c = 1
    end function bad_cell

    !> A result with the structure of `res` and no instant (POST_CHAMP's output).
    subroutine empty_like(res, out)
        type(result_concept_t), intent(in) :: res
        type(result_concept_t), intent(inout) :: out
        call result_fields_init(out, res%type_name(), max(res%n_stored, 1_i4))
        out%mesh = res%mesh
        out%dofs = res%dofs
        out%has_structure = res%has_structure
        if (res%has_structure) then
            out%model = res%model
            out%materials = res%materials
            out%cara = res%cara
            out%choc = res%choc
            out%model_name = res%model_name
        end if
        out%has_state = .false.
    end subroutine empty_like

    !> A cell field reduced to sub-point 3 (layer - 1) + level on every cell that has
    !> sub-points (the other cells of `cells` copied).
    !>  st : STATUS_MODEL_ERROR 'cell N: ...' when a cell has fewer sub-points (naming its
    !>       layers), or when the field is not an element field
    subroutine extract_subpoint(f, layer, level, cells, out, st)
        type(field_t), intent(in) :: f
        integer(i4), intent(in) :: layer     ! NUME_COUCHE, >= 1 (the catalog)
        integer(i4), intent(in) :: level     ! 1 INF, 2 MOY, 3 SUP within the layer
        logical, intent(in) :: cells(:)
        type(field_t), intent(out) :: out
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: n_points(:), n_sub(:)
        integer(i4) :: c, p, n_cmp, s_in, sub
        integer(i8) :: from, to
        if (.not. field_is_cell_field(f)) then
            call set_error(st, STATUS_MODEL_ERROR, 'EXTR_COQUE takes fields by element ' // &
                '(ELGA, ELNO), not ' // f%quantity)
            return
        end if
        call field_init_cells(out, f%location, f%quantity, f%components, f%n_cells, st)
        if (st%failed()) return
        n_points = merge(f%n_points, 0_i4, cells)
        allocate (n_sub(f%n_cells), source=1_i4)
        do c = 1, f%n_cells
            if (n_points(c) == 0 .or. f%n_subpoints(c) == 1) cycle
            ! the layer is compared before 3 (layer - 1) + level is formed: NUME_COUCHE is
            ! any positive integer the deck gives, 3 NUME_COUCHE may not fit in 32 bits
            if (layer > f%n_subpoints(c) / 3) then
                call set_error(st, STATUS_MODEL_ERROR, 'cell ' // to_text(c) // ': no ' // &
                    'layer ' // to_text(layer) // ': it has ' // &
                    to_text(f%n_subpoints(c) / 3) // ' layer(s) (COQUE_NCOU of AFFE_CARA_ELEM)')
                return
            end if
        end do
        call field_define_cells(out, n_points, n_sub, f%cell_set, f%sets, st)
        if (st%failed()) return
        sub = 1
        if (any(n_points > 0 .and. f%n_subpoints > 1)) sub = 3 * (layer - 1) + level
        do c = 1, f%n_cells
            if (n_points(c) == 0) cycle
            n_cmp = size(f%sets(f%cell_set(c))%cmp, kind=i4)
            s_in = 1
            if (f%n_subpoints(c) > 1) s_in = sub
            do p = 1, n_points(c)
                from = f%offset(c) + (int(p - 1, i8) * f%n_subpoints(c) + (s_in - 1)) * n_cmp
                to = out%offset(c) + int(p - 1, i8) * n_cmp
                out%values(to + 1:to + n_cmp) = f%values(from + 1:from + n_cmp)
            end do
        end do
    end subroutine extract_subpoint

    !> The instants asked for (default every stored one).
    subroutine post_instants(cmd, res, indices, st)
        type(command_t), intent(in) :: cmd
        class(result_fields_t), intent(in) :: res
        integer(i4), allocatable, intent(out) :: indices(:)
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: numbers(:)
        real(dp), allocatable :: times(:)
        real(dp) :: precision
        character(len=:), allocatable :: criterion
        class(concept_t), pointer :: p
        integer :: k
        precision = 1.0e-6_dp
        criterion = 'RELATIF'
        if (cmd%has('PRECISION')) call cmd%get_real('PRECISION', precision, st)
        if (st%ok() .and. cmd%has('CRITERE')) call cmd%get_text('CRITERE', criterion, st)
        if (st%failed()) return
        if (cmd%has('NUME_ORDRE')) then
            call cmd%get_ints('NUME_ORDRE', numbers, st)
            if (st%failed()) return
            allocate (indices(size(numbers)))
            do k = 1, size(numbers)
                call result_find(res, indices(k), st, nume_ordre=numbers(k))
                if (st%failed()) then
                    call relocate(cmd, 'NUME_ORDRE', st)
                    return
                end if
            end do
            return
        end if
        if (cmd%has('INST')) then
            call cmd%get_reals('INST', times, st)
        else if (cmd%has('LIST_INST')) then
            call cmd%get_concept('LIST_INST', p, st)
            if (st%failed()) return
            select type (p)
            type is (real_list_t)
                times = p%values
            end select
        else
            indices = [(k, k = 1, res%n_stored)]
            return
        end if
        if (st%failed()) return
        allocate (indices(size(times)))
        do k = 1, size(times)
            call result_find(res, indices(k), st, inst=times(k), precision=precision, &
                criterion=criterion)
            if (st%failed()) then
                call relocate(cmd, trim(merge('INST     ', 'LIST_INST', cmd%has('INST'))), st)
                return
            end if
        end do
    end subroutine post_instants

    !> TOUT / GROUP_MA (every cell by default).
    subroutine post_cells(cmd, res, cells, st)
        type(command_t), intent(in) :: cmd
        type(result_concept_t), intent(in) :: res
        logical, allocatable, intent(out) :: cells(:)
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        integer(i4) :: k, g
        allocate (cells(res%mesh%n_cells), source=.not. cmd%has('GROUP_MA'))
        if (.not. cmd%has('GROUP_MA')) return
        call cmd%get_texts('GROUP_MA', names, st)
        if (st%failed()) return
        do k = 1, size(names)
            g = find_cell_group(res%mesh, names(k)%s, st)
            if (st%failed()) then
                call relocate(cmd, 'GROUP_MA', st)
                return
            end if
            cells(cells_of_group(res%mesh, g)) = .true.
        end do
    end subroutine post_cells

end module post_champ_command
