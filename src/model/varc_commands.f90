!> AFFE_MATERIAU's AFFE_VARC occurrences (U4.43.03; Code_Aster's c_affe_varc.py): the
!> command variables of a material field (model_varc). Called by run_affe_materiau.
module varc_commands
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use strings, only: to_text, to_upper
    use deck_concept, only: concept_t, concept_display_name
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t
    use mesh_command_support, only: group_cells
    use function_concept, only: function_concept_t
    use field_types, only: FIELD_NOEU, FIELD_CART, FIELD_ELEM, field_location_name
    use field_concept, only: field_concept_t
    use result_fields, only: result_fields_t, result_field_index
    use model_varc, only: varc_field_t, varc_source_t, varc_add_source, VARC_NAMES, &
        VARC_TEMP, VARC_HYDR, VARC_SECH
    implicit none
    private

    public :: affe_varc_occurrences

contains

    !> Every AFFE_VARC occurrence of `cmd` into `varc` (on the cells of `mesh`).
    !>  st : out, located at the keyword: a command variable other than TEMP, HYDR, SECH (not
    !>       built), a CHAM_GD of another quantity (TEMP_R for TEMP and SECH, HYDR_R for
    !>       HYDR) or on another mesh, an EVOL without
    !>       NOM_CHAM at some instant or of another mesh, a missing group
    subroutine affe_varc_occurrences(ctx, cmd, mesh, varc, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(mesh_t), intent(in) :: mesh
        type(varc_field_t), intent(inout) :: varc
        type(status_t), intent(out) :: st
        type(keyword_set_t) :: occ
        type(varc_source_t) :: source
        integer(i4), allocatable :: cells(:)
        integer(i4) :: i, c
        do i = 1, cmd%count('AFFE_VARC')
            occ = cmd%occurrence('AFFE_VARC', i)
            call read_source(occ, mesh, source, st)
            if (st%failed()) return
            if (occ%has('GROUP_MA')) then
                call group_cells(occ, 'GROUP_MA', mesh, cells, st)
                if (st%failed()) return
            else
                cells = [(c, c = 1, mesh%n_cells)]
            end if
            call varc_add_source(varc, source, cells)
            call ctx%write_mess('    ' // source%label // ' (VALE_REF ' // &
                to_text(source%vale_ref) // ') on ' // to_text(size(cells, kind=i4)) // &
                ' cells, ' // to_text(source%n) // ' instant(s)')
        end do
    end subroutine affe_varc_occurrences

    ! NOM_VARC, VALE_REF, and the field(s) of CHAM_GD or EVOL.
    subroutine read_source(occ, mesh, source, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        type(varc_source_t), intent(out) :: source
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: name
        class(concept_t), pointer :: p
        integer(i4) :: v
        call occ%get_text('NOM_VARC', name, st)
        if (st%failed()) return
        source%variable = 0
        do v = 1, size(VARC_NAMES, kind=i4)
            if (to_upper(name) == VARC_NAMES(v)) source%variable = v
        end do
        if (source%variable == 0) then
            call occ%error_at('NOM_VARC', 'the command variable ' // to_upper(name) // &
                ' is not built (parasol builds the temperature TEMP, the hydration HYDR ' // &
                'and the drying SECH)', st, code=STATUS_NOT_IMPLEMENTED)
            return
        end if
        if (occ%has('VALE_REF')) call occ%get_real('VALE_REF', source%vale_ref, st)
        if (st%failed()) return
        if (occ%has('CHAM_GD')) then
            call occ%get_concept('CHAM_GD', p, st)
            if (st%failed()) return
            call field_source(occ, p, mesh, source, st)
        else
            call occ%get_concept('EVOL', p, st)
            if (st%failed()) return
            call evol_source(occ, p, mesh, source, st)
        end if
    end subroutine read_source

    subroutine field_source(occ, p, mesh, source, st)
        type(keyword_set_t), intent(in) :: occ
        class(concept_t), intent(in) :: p
        type(mesh_t), intent(in) :: mesh
        type(varc_source_t), intent(inout) :: source
        type(status_t), intent(out) :: st
        select type (p)
        type is (field_concept_t)
            call check_varc_field(p%field, mesh, source%variable, 'CHAM_GD', occ, st)
            if (st%failed()) return
            source%label = 'AFFE_VARC ' // VARC_NAMES(source%variable) // ' (CHAM_GD ' // &
                concept_display_name(p) // ')'
            source%evol = .false.
            source%n = 1
            allocate (source%inst(1), source%fields(1))
            source%inst = 0.0_dp
            source%fields(1) = p%field
        class default
            call occ%error_at('CHAM_GD', 'expected a field, got ' // p%type_name(), st)
        end select
    end subroutine field_source

    subroutine evol_source(occ, p, mesh, source, st)
        type(keyword_set_t), intent(in) :: occ
        class(concept_t), intent(in) :: p
        type(mesh_t), intent(in) :: mesh
        type(varc_source_t), intent(inout) :: source
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: nom_cham, prol
        class(concept_t), pointer :: f
        integer(i4) :: k, j
        ! Code_Aster's default NOM_CHAM (affe_materiau_ops): HYDR_ELNO for HYDR, else the
        ! variable's name
        nom_cham = VARC_NAMES(source%variable)
        if (source%variable == VARC_HYDR) nom_cham = 'HYDR_ELNO'
        if (occ%has('NOM_CHAM')) call occ%get_text('NOM_CHAM', nom_cham, st)
        if (st%failed()) return
        select type (p)
        class is (result_fields_t)
            if (p%n_stored == 0) then
                call occ%error_at('EVOL', concept_display_name(p) // ' holds no instant', &
                                  st, code=STATUS_MODEL_ERROR)
                return
            end if
            source%label = 'AFFE_VARC ' // VARC_NAMES(source%variable) // ' (EVOL ' // &
                concept_display_name(p) // ')'
            source%evol = .true.
            source%n = p%n_stored
            allocate (source%inst(p%n_stored), source%fields(p%n_stored))
            do k = 1, p%n_stored
                j = result_field_index(p, k, nom_cham)
                if (j == 0) then
                    call occ%error_at('EVOL', concept_display_name(p) // ' has no ' // &
                        to_upper(nom_cham) // ' field at INST ' // to_text(p%inst(k)), st, &
                        code=STATUS_MODEL_ERROR)
                    return
                end if
                call check_varc_field(p%stored(k)%items(j)%field, mesh, source%variable, &
                                      'EVOL', occ, st)
                if (st%failed()) return
                source%inst(k) = p%inst(k)
                source%fields(k) = p%stored(k)%items(j)%field
                if (k > 1) then
                    if (.not. source%inst(k) > source%inst(k - 1)) then
                        call occ%error_at('EVOL', concept_display_name(p) // &
                            ': its instants do not increase', st, code=STATUS_MODEL_ERROR)
                        return
                    end if
                end if
            end do
        class default
            call occ%error_at('EVOL', 'expected a result (evol_ther), got ' // &
                              p%type_name(), st)
            return
        end select
        call occ%get_text('PROL_GAUCHE', prol, st)
        if (st%ok()) source%prol_gauche = prol
        if (st%ok()) call occ%get_text('PROL_DROITE', prol, st)
        if (st%ok()) source%prol_droite = prol
        if (st%ok() .and. occ%has('FONC_INST')) then
            call occ%get_concept('FONC_INST', f, st)
            if (st%failed()) return
            select type (f)
            class is (function_concept_t)
                source%fonc_inst => f
            class default
                call occ%error_at('FONC_INST', 'expected a function of INST', st)
            end select
        end if
    end subroutine evol_source

    ! A field of the variable's quantity (TEMP_R for TEMP and SECH, HYDR_R for HYDR, as
    ! Code_Aster's command variables) on the nodes or cells of `mesh` (ELNO too for HYDR,
    ! whose results hold HYDR_ELNO).
    subroutine check_varc_field(f, mesh, variable, key, occ, st)
        use field_types, only: field_t, FIELD_ELNO
        type(field_t), intent(in) :: f
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: variable
        character(len=*), intent(in) :: key
        type(keyword_set_t), intent(in) :: occ
        type(status_t), intent(out) :: st
        character(len=6) :: quantity
        logical :: cells
        quantity = merge('HYDR_R', 'TEMP_R', variable == VARC_HYDR)
        cells = f%location == FIELD_CART .or. f%location == FIELD_ELEM .or. &
            (variable /= VARC_TEMP .and. f%location == FIELD_ELNO)
        if (.not. allocated(f%quantity)) then
            call occ%error_at(key, 'the field is empty', st, code=STATUS_MODEL_ERROR)
        else if (f%quantity /= quantity) then
            call occ%error_at(key, 'expected a ' // trim(merge('temperature', &
                'hydration  ', variable == VARC_TEMP)) // ' field (' // quantity // &
                ') for NOM_VARC=''' // VARC_NAMES(variable) // ''', got ' // f%quantity, st, &
                code=STATUS_MODEL_ERROR)
        else if (f%location == FIELD_NOEU .and. f%n_nodes /= mesh%n_nodes) then
            call occ%error_at(key, 'the field has ' // to_text(f%n_nodes) // &
                ' nodes, the mesh ' // to_text(mesh%n_nodes) // ' (another mesh?)', st, &
                code=STATUS_MODEL_ERROR)
        else if (cells .and. f%n_cells /= mesh%n_cells) then
            call occ%error_at(key, 'the field has ' // to_text(f%n_cells) // &
                ' cells, the mesh ' // to_text(mesh%n_cells) // ' (another mesh?)', st, &
                code=STATUS_MODEL_ERROR)
        else if (f%location /= FIELD_NOEU .and. .not. cells) then
            call occ%error_at(key, 'a field ' // field_location_name(f) // ' is not read ' // &
                'here for ' // VARC_NAMES(variable) // ' (NOEU, CART or ELEM' // &
                trim(merge(', ELNO', '      ', variable /= VARC_TEMP)) // ')', st, &
                code=STATUS_NOT_IMPLEMENTED)
        end if
    end subroutine check_varc_field

end module varc_commands
