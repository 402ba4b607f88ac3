!> CREA_RESU (Code_Aster U4.44.12, code_aster/Cata/Commands/crea_resu.py), OPERATION='AFFE':
!> a result of TYPE_RESU (EVOL_ELAS, EVOL_NOLI, EVOL_THER, EVOL_SECH, EVOL_VARC, EVOL_CHAR)
!> made of fields given per instant (doc/fields.md, "CREA_RESU"). Each AFFE occurrence puts
!> CHAM_GD under NOM_CHAM at every instant of INST or LIST_INST (NUME_INIT .. NUME_FIN of
!> it): at a stored instant equal within PRECISION (default 0, CRITERE RELATIF: the same
!> number) the field is replaced, otherwise a new instant is stored with the next NUME_ORDRE
!> (the first is 1), as Code_Aster's crtype. A field of functions (NOEU_TEMP_F, ...) is
!> evaluated at each instant with X, Y, Z of the node and INST. RESULTAT (or reuse) adds to
!> an existing result. MODELE, CHAM_MATER, CARA_ELEM record the structure later commands
!> compute on.
module crea_resu_command
    use keyword_relocation, only: relocate => relocate_error
    use kinds, only: dp, i4
    use status, only: status_t, set_error, clear_status, STATUS_MODEL_ERROR, &
        STATUS_NOT_IMPLEMENTED
    use strings, only: string_t, to_text, to_lower, real_e13
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t
    use model_concept, only: model_concept_t
    use material_concept, only: material_field_concept_t
    use cara_elem_concept, only: cara_elem_concept_t
    use model_cara_elem, only: cara_elem_init
    use model_material, only: material_field_init
    use real_list, only: real_list_t
    use function_concept, only: param_binding_t
    use field_types, only: field_t, FIELD_NOEU, field_check_finite
    use field_quantities, only: quantity_is_function, quantity_real_twin
    use field_concept, only: field_concept_t
    use field_support, only: mesh_of_support
    use result_fields, only: result_fields_t, result_fields_init, result_add_instant, &
        result_put_field, result_find
    use analysis_result, only: result_concept_t
    use crea_resu_prep_varc, only: run_prep_varc
    implicit none
    private

    public :: run_crea_resu

contains

    !> Handler of CREA_RESU (registered with reuse: reuse=R adds to R in place).
    !>  st : located errors (an operation not built, a field of another mesh, an instant
    !>       list that selects nothing, a function that cannot be evaluated)
    subroutine run_crea_resu(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(result_concept_t), allocatable, target :: made
        type(result_concept_t), pointer :: res
        class(concept_t), pointer :: p
        character(len=:), allocatable :: operation, kind
        integer(i4) :: k, n_before
        call cmd%get_text('OPERATION', operation, st)
        if (st%ok()) call cmd%get_text('TYPE_RESU', kind, st)
        if (st%failed()) return
        if (operation == 'PREP_VARC') then      ! the layers of plates (elem's module)
            call run_prep_varc(ctx, cmd, result, st)
            return
        end if
        if (operation /= 'AFFE') then
            call cmd%error_at('OPERATION', 'OPERATION=''' // operation // ''' is not built ' // &
                'in parasol (AFFE and PREP_VARC are)', st, STATUS_NOT_IMPLEMENTED)
            return
        end if
        kind = to_lower(kind)
        res => null()
        if (associated(cmd%reuse)) then
            p => cmd%reuse
        else if (cmd%has('RESULTAT')) then
            call cmd%get_concept('RESULTAT', p, st)
            if (st%failed()) return
        else
            p => null()
        end if
        if (associated(p)) then
            select type (p)
            type is (result_concept_t)
                if (associated(cmd%reuse)) then
                    res => p
                else
                    allocate (made, source=p)
                    res => made
                end if
            class default
                call cmd%error_at('RESULTAT', 'CREA_RESU adds to a result of MECA_STATIQUE, ' // &
                    'STAT_NON_LINE or CREA_RESU, not a ' // p%type_name(), st)
                return
            end select
            if (res%type_name() /= kind) then
                call cmd%error_at('TYPE_RESU', 'the result to complete is a ' // &
                    res%type_name() // ', not a ' // kind, st, STATUS_MODEL_ERROR)
                return
            end if
        else
            allocate (made)
            call result_fields_init(made, kind, 4_i4)
            res => made
        end if
        n_before = res%n_stored
        do k = 1, cmd%count('AFFE')
            call affe_occurrence(cmd%occurrence('AFFE', k), res, st)
            if (st%failed()) return
        end do
        call ctx%write_mess('    CREA_RESU: ' // kind // ', ' // to_text(res%n_stored) // &
            ' instant(s) (' // to_text(res%n_stored - n_before) // ' new)')
        if (allocated(made)) call move_alloc(made, result)
    end subroutine run_crea_resu

    !> One AFFE occurrence.
    subroutine affe_occurrence(occ, res, st)
        type(keyword_set_t), intent(in) :: occ
        type(result_concept_t), intent(inout) :: res
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        type(field_concept_t), pointer :: src
        type(mesh_t), pointer :: mesh
        type(field_t) :: f
        real(dp), allocatable :: times(:)
        character(len=:), allocatable :: name, criterion
        real(dp) :: precision
        integer(i4) :: k, at
        call occ%get_concept('CHAM_GD', p, st)
        if (st%failed()) return
        select type (p)
        type is (field_concept_t)
            src => p
        class default
            call occ%error_at('CHAM_GD', 'expected a field (CREA_CHAMP), got ' // &
                p%type_name(), st)
            return
        end select
        call mesh_of_support(src%support, mesh, st)
        if (st%failed()) then
            call relocate(occ, 'CHAM_GD', st)
            return
        end if
        if (res%mesh%n_nodes == 0 .and. res%n_stored == 0) then
            res%mesh = mesh
        else if (res%mesh%n_nodes /= mesh%n_nodes .or. res%mesh%n_cells /= mesh%n_cells) then
            call occ%error_at('CHAM_GD', 'the field lives on another mesh than the ' // &
                'result''s (' // to_text(mesh%n_nodes) // ' nodes, the result''s ' // &
                to_text(res%mesh%n_nodes) // ')', st, STATUS_MODEL_ERROR)
            return
        end if
        call structure_of(occ, res, st)
        if (st%ok()) call occ%get_text('NOM_CHAM', name, st)
        if (st%ok()) call instants_of(occ, times, st)
        if (st%failed()) return
        precision = 0.0_dp
        criterion = 'RELATIF'
        if (occ%has('PRECISION')) call occ%get_real('PRECISION', precision, st)
        if (st%ok() .and. occ%has('CRITERE')) call occ%get_text('CRITERE', criterion, st)
        if (st%failed()) return
        do k = 1, size(times)
            call instant_index(res, times(k), precision, criterion, at)
            if (quantity_is_function(src%field%quantity)) then
                call evaluated(src%field, mesh, times(k), f, st)
                if (st%failed()) then
                    st%message = 'CHAM_GD at INST ' // real_e13(times(k)) // ': ' // st%message
                    call relocate(occ, 'CHAM_GD', st)
                    return
                end if
            else
                f = src%field
            end if
            call result_put_field(res, at, name, f)
        end do
    end subroutine affe_occurrence

    !> The stored index of instant t (within precision), a new instant with the next
    !> NUME_ORDRE otherwise.
    subroutine instant_index(res, t, precision, criterion, at)
        type(result_concept_t), intent(inout) :: res
        real(dp), intent(in) :: t, precision
        character(len=*), intent(in) :: criterion
        integer(i4), intent(out) :: at
        type(status_t) :: st
        integer(i4) :: next
        at = 0
        if (res%n_stored > 0) then
            if (criterion == 'ABSOLU') then
                call result_find(res, at, st, inst=t, precision=precision, criterion='ABSOLU')
            else
                call result_find(res, at, st, inst=t, precision=precision)
            end if
            if (st%ok()) return
            call clear_status(st)
        end if
        next = 1
        if (res%n_stored > 0) next = maxval(res%nume_ordre(1:res%n_stored)) + 1
        call result_add_instant(res, next, t, at)
    end subroutine instant_index

    !> INST, or LIST_INST from NUME_INIT to NUME_FIN (1-based, default the whole list).
    subroutine instants_of(occ, times, st)
        type(keyword_set_t), intent(in) :: occ
        real(dp), allocatable, intent(out) :: times(:)
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        integer(i4) :: first, last
        if (occ%has('INST')) then
            call occ%get_reals('INST', times, st)
            return
        end if
        if (.not. occ%has('LIST_INST')) then
            call occ%error_at('NOM_CHAM', 'give INST or LIST_INST (the instants of the ' // &
                'field)', st, STATUS_MODEL_ERROR)
            return
        end if
        call occ%get_concept('LIST_INST', p, st)
        if (st%failed()) return
        select type (p)
        type is (real_list_t)
            first = 1
            last = size(p%values, kind=i4)
            if (occ%has('NUME_INIT')) call occ%get_int('NUME_INIT', first, st)
            if (st%ok() .and. occ%has('NUME_FIN')) call occ%get_int('NUME_FIN', last, st)
            if (st%failed()) return
            last = min(last, size(p%values, kind=i4))
            if (first < 1 .or. first > last) then
                call occ%error_at('LIST_INST', 'NUME_INIT .. NUME_FIN selects no instant ' // &
                    'of the list (' // to_text(size(p%values)) // ' instants)', st, &
                    STATUS_MODEL_ERROR)
                return
            end if
            times = p%values(first:last)
        class default
            call occ%error_at('LIST_INST', 'expected a list of reals (DEFI_LIST_REEL)', st)
        end select
    end subroutine instants_of

    !> MODELE, CHAM_MATER, CARA_ELEM of an occurrence: the structure of the result.
    subroutine structure_of(occ, res, st)
        type(keyword_set_t), intent(in) :: occ
        type(result_concept_t), intent(inout) :: res
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        if (.not. occ%has('MODELE')) return
        call occ%get_concept('MODELE', p, st)
        if (st%failed()) return
        select type (p)
        type is (model_concept_t)
            res%model = p%model
            res%dofs = p%dofs
            res%model_name = p%name
            res%has_structure = .true.
            if (.not. allocated(res%choc)) allocate (res%choc(p%mesh%n_cells), source=.false.)
            if (.not. allocated(res%materials%cell_material)) &
                call material_field_init(res%materials, p%mesh)
            if (.not. allocated(res%cara%has_coque)) call cara_elem_init(res%cara, p%mesh)
        end select
        if (occ%has('CHAM_MATER')) then
            call occ%get_concept('CHAM_MATER', p, st)
            if (st%failed()) return
            select type (p)
            type is (material_field_concept_t)
                res%materials = p%field
            end select
        end if
        if (occ%has('CARA_ELEM')) then
            call occ%get_concept('CARA_ELEM', p, st)
            if (st%failed()) return
            select type (p)
            type is (cara_elem_concept_t)
                res%cara = p%cara
            end select
        end if
    end subroutine structure_of

    !> A field of functions evaluated at instant t: each node's functions of X, Y, Z, INST
    !> (a NOEU field; other locations are not built).
    subroutine evaluated(fun, mesh, t, f, st)
        type(field_t), intent(in) :: fun
        type(mesh_t), intent(in) :: mesh
        real(dp), intent(in) :: t
        type(field_t), intent(out) :: f
        type(status_t), intent(out) :: st
        type(param_binding_t), allocatable :: bindings(:)
        integer(i4) :: k, n, i
        if (fun%location /= FIELD_NOEU) then
            call set_error(st, STATUS_NOT_IMPLEMENTED, 'a field of functions at the nodes ' // &
                '(NOEU_*_F) is evaluated per instant; other locations are not built')
            return
        end if
        allocate (bindings(size(fun%functions)))
        do k = 1, size(fun%functions)
            call fun%functions(k)%f%bind(['X   ', 'Y   ', 'Z   ', 'INST'], bindings(k))
        end do
        call field_init_nodes_like(fun, f, st)
        if (st%failed()) return
        do n = 1, fun%n_nodes
            do i = 1, size(fun%components)
                if (.not. fun%node_has(i, n)) cycle
                k = nint(fun%node_values(i, n))
                call fun%functions(k)%f%evaluate(bindings(k), [mesh%coords(:, n), t], &
                    f%node_values(i, n), st)
                if (st%failed()) return
                f%node_has(i, n) = .true.
            end do
        end do
        call field_check_finite(f, st)
    end subroutine evaluated

    !> An empty NOEU field of the real twin of a function field's quantity, same components.
    subroutine field_init_nodes_like(fun, f, st)
        use field_types, only: field_init_nodes
        type(field_t), intent(in) :: fun
        type(field_t), intent(out) :: f
        type(status_t), intent(out) :: st
        call field_init_nodes(f, quantity_real_twin(fun%quantity), fun%components, &
            fun%n_nodes, st)
    end subroutine field_init_nodes_like

end module crea_resu_command
