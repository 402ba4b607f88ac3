!> CREA_CHAMP (Code_Aster U4.72.04, code_aster/Cata/Commands/crea_champ.py): makes a field
!> concept (field_concept) of TYPE_CHAM = <location>_<quantity> by OPERATION:
!>   AFFE  constant values (VALE) or functions (VALE_F, for *_F quantities) per component
!>         (NOM_CMP) on TOUT / GROUP_MA / GROUP_NO / NOEUD / MAILLE of MAILLAGE or MODELE;
!>         later occurrences override earlier ones where they meet. A NOEU field gets the
!>         nodes (of the cells) named; a CART field the cells; an element field (ELGA, ELNO,
!>         ELEM: MODELE required) the cells carrying an element, at every point of each
!>         (field_layout), and with PROL_ZERO='OUI' every cell of the model, zeros where no
!>         value was given;
!>   EXTR  a field of a RESULTAT at NUME_ORDRE or INST (result_access), or the GEOMETRIE
!>         (NOEU_GEOM_R: X Y Z) of a MAILLAGE; TYPE_CHAM must be the field's;
!>   ASSE, COMB, EVAL  see crea_champ_combine;
!>   NORMALE  the nodal normals of boundary cells (crea_champ_normale);
!>   DISC  a field moved to another location (crea_champ_disc).
!> Every error names what exists: the quantity's components, the field's TYPE_CHAM, the
!> groups of the mesh.
module crea_champ_command
    use keyword_relocation, only: relocate => relocate_error
    use mesh_command_support, only: mark_cells, mark_nodes, mark_nodes_of_cells
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, &
        STATUS_NOT_IMPLEMENTED
    use strings, only: string_t, to_text, to_upper
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t, concept_ref_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t
    use model_types, only: model_t
    use function_concept, only: function_concept_t
    use field_quantities, only: quantity_components, quantity_component_index, &
        quantity_is_function, components_text
    use field_types, only: field_t, component_set_t, field_init_nodes, field_init_cells, &
        field_define_cells, parse_type_cham, field_type_cham, field_add_function, &
        field_check_finite, FIELD_NOEU, FIELD_CART, FIELD_LOCATION_NAMES
    use field_concept, only: field_concept_t
    use field_layout, only: element_point_count
    use field_support, only: mesh_of_support, model_of_support
    use result_fields, only: result_fields_t, result_find
    use result_access, only: result_field_at
    use crea_champ_combine, only: crea_asse, crea_comb, crea_eval, component_sets_of, &
        read_support
    use crea_champ_normale, only: crea_normale
    use crea_champ_disc, only: crea_disc
    implicit none
    private

    public :: run_crea_champ, selected_nodes, selected_cells

contains

    !> Handler of CREA_CHAMP (doc/architecture.md "Writing a command handler").
    !>  st : located errors at the keyword at fault
    subroutine run_crea_champ(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(field_concept_t), allocatable :: out
        character(len=:), allocatable :: type_cham, operation, quantity
        integer(i4) :: location
        call cmd%get_text('TYPE_CHAM', type_cham, st)
        if (st%ok()) call cmd%get_text('OPERATION', operation, st)
        if (st%failed()) return
        call parse_type_cham(type_cham, location, quantity, st)
        if (st%failed()) then
            call relocate(cmd, 'TYPE_CHAM', st)
            return
        end if
        if (index(' AFFE ASSE COMB ', ' ' // operation // ' ') > 0 .and. &
            cmd%count(operation) == 0) then
            call cmd%error_at('OPERATION', 'OPERATION=''' // operation // ''' takes its ' // &
                'fields in ' // operation // '=_F(...) occurrences: give at least one', st, &
                STATUS_MODEL_ERROR)
            return
        end if
        allocate (out)
        select case (operation)
        case ('AFFE')
            call crea_affe(cmd, location, quantity, out, st)
        case ('EXTR')
            call crea_extr(cmd, type_cham, out, st)
        case ('ASSE')
            call crea_asse(cmd, location, quantity, out, st)
        case ('COMB')
            call crea_comb(cmd, location, quantity, out, st)
        case ('EVAL')
            call crea_eval(cmd, location, quantity, out, st)
        case ('NORMALE')
            call crea_normale(cmd, type_cham, out, st)
        case ('DISC')
            call crea_disc(cmd, location, quantity, out, st)
        case default
            call cmd%error_at('OPERATION', 'OPERATION=''' // operation // ''' is not ' // &
                'built in parasol (AFFE, EXTR, ASSE, COMB, EVAL, NORMALE and DISC are)', st, &
                STATUS_NOT_IMPLEMENTED)
        end select
        if (st%failed()) return
        call field_check_finite(out%field, st)
        if (st%failed()) then
            call relocate(cmd, 'OPERATION', st)
            return
        end if
        call ctx%write_mess('    CREA_CHAMP ' // operation // ': ' // &
            field_type_cham(out%field) // ' with ' // components_text(out%field%components))
        call move_alloc(out, result)
    end subroutine run_crea_champ

    !> OPERATION='AFFE' (module header).
    subroutine crea_affe(cmd, location, quantity, out, st)
        type(command_t), intent(in) :: cmd
        integer(i4), intent(in) :: location
        character(len=*), intent(in) :: quantity
        type(field_concept_t), intent(inout) :: out
        type(status_t), intent(out) :: st
        type(mesh_t), pointer :: mesh
        type(model_t), pointer :: model
        type(string_t), allocatable :: field_cmps(:), names(:)
        logical, allocatable :: assigned(:, :), where(:)
        real(dp), allocatable :: values(:, :), vals(:)
        integer(i4), allocatable :: cols(:)
        type(keyword_set_t) :: occ
        integer(i4) :: k, j, n_entities
        logical :: prol_zero
        call read_support(cmd, out, mesh, model, st)
        if (st%failed()) return
        if (location /= FIELD_NOEU .and. location /= FIELD_CART .and. &
            .not. associated(model)) then
            call cmd%error_at('MAILLAGE', FIELD_LOCATION_NAMES(location) // ' fields are ' // &
                'defined on the elements of a model: give MODELE', st, STATUS_MODEL_ERROR)
            return
        end if
        call affe_components(cmd, quantity, field_cmps, st)
        if (st%failed()) return
        n_entities = mesh%n_cells
        if (location == FIELD_NOEU) n_entities = mesh%n_nodes
        allocate (assigned(size(field_cmps), n_entities), source=.false.)
        allocate (values(size(field_cmps), n_entities), source=0.0_dp)
        if (location == FIELD_NOEU) then
            call field_init_nodes(out%field, quantity, field_cmps, n_entities, st)
        else
            call field_init_cells(out%field, location, quantity, field_cmps, n_entities, st)
        end if
        if (st%failed()) return
        do k = 1, cmd%count('AFFE')
            occ = cmd%occurrence('AFFE', k)
            call occ%get_texts('NOM_CMP', names, st)
            if (st%failed()) return
            allocate (cols(size(names)))
            do j = 1, size(names)
                cols(j) = position_of(out%field%components, to_upper(names(j)%s))
            end do
            call affe_values(occ, quantity, size(names, kind=i4), out%field, vals, st)
            if (st%failed()) return
            if (location == FIELD_NOEU) then
                call selected_nodes(occ, mesh, where, st)
            else
                call selected_cells(occ, mesh, where, st)
            end if
            if (st%failed()) return
            do j = 1, size(cols)
                where (where)
                    assigned(cols(j), :) = .true.
                    values(cols(j), :) = vals(j)
                end where
            end do
            deallocate (cols)
        end do
        if (location == FIELD_NOEU) then
            out%field%node_has = assigned
            out%field%node_values = values
            return
        end if
        prol_zero = .false.
        if (cmd%has('PROL_ZERO')) call flag(cmd, 'PROL_ZERO', prol_zero, st)
        call fill_cells(out%field, mesh, model, assigned, values, prol_zero, st)
        if (st%failed()) call relocate(cmd, 'AFFE', st)
    end subroutine crea_affe

    !> Every NOM_CMP of the AFFE occurrences, checked against the quantity, in its order.
    subroutine affe_components(cmd, quantity, cmps, st)
        type(command_t), intent(in) :: cmd
        character(len=*), intent(in) :: quantity
        type(string_t), allocatable, intent(out) :: cmps(:)
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:), all(:)
        logical, allocatable :: used(:)
        type(keyword_set_t) :: occ
        integer(i4) :: k, j, rank
        all = quantity_components(quantity, 999_i4)
        allocate (used(size(all)), source=.false.)
        do k = 1, cmd%count('AFFE')
            occ = cmd%occurrence('AFFE', k)
            call occ%get_texts('NOM_CMP', names, st)
            if (st%failed()) return
            do j = 1, size(names)
                rank = quantity_component_index(quantity, names(j)%s)
                if (rank == 0) then
                    call occ%error_at('NOM_CMP', quantity // ' has no component ' // &
                        names(j)%s // ' (' // components_text(quantity_components(quantity)) &
                        // ')', st, STATUS_MODEL_ERROR)
                    return
                end if
                used(rank) = .true.
            end do
        end do
        cmps = pack(all, used)
    end subroutine affe_components

    !> The values of one AFFE occurrence, one per NOM_CMP: VALE for real quantities, VALE_F
    !> (functions, stored in the field) for *_F quantities.
    subroutine affe_values(occ, quantity, n_cmp, f, vals, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: quantity
        integer(i4), intent(in) :: n_cmp
        type(field_t), intent(inout) :: f
        real(dp), allocatable, intent(out) :: vals(:)
        type(status_t), intent(out) :: st
        type(concept_ref_t), allocatable :: refs(:)
        character(len=:), allocatable :: key
        integer :: j
        if (quantity_is_function(quantity)) then
            key = 'VALE_F'
        else
            key = 'VALE'
        end if
        if (.not. occ%has(key)) then
            call occ%error_at('NOM_CMP', quantity // ' takes ' // key // ' (' // &
                trim(merge('functions', 'reals    ', key == 'VALE_F')) // ')', st, &
                STATUS_MODEL_ERROR)
            return
        end if
        if (key == 'VALE') then
            call occ%get_reals('VALE', vals, st)
        else
            call occ%get_concepts('VALE_F', refs, st)
            if (st%ok()) then
                allocate (vals(size(refs)))
                do j = 1, size(refs)
                    call function_index(refs(j)%ptr, f, vals(j), st)
                    if (st%failed()) then
                        call relocate(occ, 'VALE_F', st)
                        return
                    end if
                end do
            end if
        end if
        if (st%failed()) return
        if (size(vals) /= n_cmp) then
            call occ%error_at(key, 'give one value per NOM_CMP (' // to_text(n_cmp) // &
                ' component(s), ' // to_text(size(vals)) // ' value(s))', st, &
                STATUS_MODEL_ERROR)
        end if
    end subroutine affe_values

    !> Adds a function to a function-valued field; its index is the value stored.
    subroutine function_index(ptr, f, index, st)
        class(concept_t), pointer, intent(in) :: ptr
        type(field_t), intent(inout) :: f
        real(dp), intent(out) :: index
        type(status_t), intent(out) :: st
        class(function_concept_t), pointer :: fn
        index = 0.0_dp
        select type (ptr)
        class is (function_concept_t)
            fn => ptr
            call field_add_function(f, fn, index)
        class default
            call set_error(st, STATUS_MODEL_ERROR, 'expected a function (DEFI_FONCTION, ' // &
                'FORMULE), got ' // ptr%type_name())
        end select
    end subroutine function_index

    !> Lays out a cell field from the per-cell values (constant on a cell): the cells with
    !> a value (every cell of the model with PROL_ZERO) get the element's points, each its
    !> own component set.
    subroutine fill_cells(f, mesh, model, assigned, values, prol_zero, st)
        type(field_t), intent(inout) :: f
        type(mesh_t), intent(in) :: mesh
        type(model_t), pointer, intent(in) :: model
        logical, intent(inout) :: assigned(:, :)
        real(dp), intent(in) :: values(:, :)
        logical, intent(in) :: prol_zero
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: n_points(:), n_sub(:), cell_set(:)
        type(component_set_t), allocatable :: sets(:)
        integer(i4) :: c, p, kind, j, n_cmp
        integer(i4) :: n_skipped
        allocate (n_points(mesh%n_cells), n_sub(mesh%n_cells), source=0_i4)
        n_skipped = 0
        do c = 1, mesh%n_cells
            kind = 0
            if (associated(model)) kind = model%element(c)
            n_points(c) = element_point_count(kind, mesh%cell_type(c), f%location)
            if (n_points(c) == 0) then
                if (any(assigned(:, c))) n_skipped = n_skipped + 1
                assigned(:, c) = .false.
            else if (prol_zero) then
                assigned(:, c) = .true.
            end if
            if (.not. any(assigned(:, c))) n_points(c) = 0
            n_sub(c) = 1
        end do
        if (all(n_points == 0)) then
            call set_error(st, STATUS_MODEL_ERROR, 'no cell given carries an element ' // &
                'of the model (' // to_text(n_skipped) // ' cell(s) without one): the ' // &
                'field would be empty')
            return
        end if
        call component_sets_of(assigned, cell_set, sets)
        call field_define_cells(f, n_points, n_sub, cell_set, sets, st)
        if (st%failed()) return
        do c = 1, mesh%n_cells
            if (n_points(c) == 0) cycle
            n_cmp = size(sets(cell_set(c))%cmp, kind=i4)
            do p = 1, n_points(c)
                do j = 1, n_cmp
                    f%values(f%offset(c) + (p - 1) * n_cmp + j) = &
                        values(sets(cell_set(c))%cmp(j), c)
                end do
            end do
        end do
    end subroutine fill_cells

    !> OPERATION='EXTR': a field of a result, or the geometry of a mesh.
    subroutine crea_extr(cmd, type_cham, out, st)
        type(command_t), intent(in) :: cmd
        character(len=*), intent(in) :: type_cham
        type(field_concept_t), intent(inout) :: out
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        type(mesh_t), pointer :: mesh
        type(field_t), pointer :: f
        character(len=:), allocatable :: name
        integer(i4) :: index, n
        if (cmd%has('MAILLAGE')) then
            call cmd%get_concept('MAILLAGE', p, st)
            if (st%ok()) call cmd%get_text('NOM_CHAM', name, st)
            if (st%failed()) return
            if (name /= 'GEOMETRIE') then
                call cmd%error_at('NOM_CHAM', 'NOM_CHAM=''' // name // ''' of a mesh is not ' &
                    // 'built in parasol (GEOMETRIE is)', st, STATUS_NOT_IMPLEMENTED)
                return
            end if
            if (type_cham /= 'NOEU_GEOM_R') then
                call cmd%error_at('TYPE_CHAM', 'the GEOMETRIE of a mesh is a NOEU_GEOM_R ' // &
                    'field, not ' // type_cham, st, STATUS_MODEL_ERROR)
                return
            end if
            call mesh_of_support(p, mesh, st)
            if (st%failed()) then
                call relocate(cmd, 'MAILLAGE', st)
                return
            end if
            out%support => p
            call field_init_nodes(out%field, 'GEOM_R', [string_t('X'), string_t('Y'), &
                string_t('Z')], mesh%n_nodes, st)
            if (st%failed()) return
            n = mesh%n_nodes
            out%field%node_values = mesh%coords(:, 1:n)
            out%field%node_has = .true.
            return
        end if
        if (.not. cmd%has('RESULTAT')) then
            call cmd%error_at('OPERATION', 'EXTR takes a field from RESULTAT or the ' // &
                'GEOMETRIE of MAILLAGE (parasol has no FISSURE, TABLE, CARA_ELEM or ' // &
                'CHARGE extraction)', st, STATUS_NOT_IMPLEMENTED)
            return
        end if
        if (cmd%has('TYPE_MAXI')) then
            call cmd%error_at('TYPE_MAXI', 'TYPE_MAXI (extremes over instants) is not ' // &
                'built in parasol: give NUME_ORDRE or INST', st, STATUS_NOT_IMPLEMENTED)
            return
        end if
        call result_instant(cmd, p, index, st)
        if (st%ok()) call cmd%get_text('NOM_CHAM', name, st)
        if (st%failed()) return
        select type (p)
        class is (result_fields_t)
            call result_field_at(p, index, name, f, st)
            if (st%failed()) then
                call relocate(cmd, 'NOM_CHAM', st)
                return
            end if
            if (field_type_cham(f) /= type_cham) then
                call cmd%error_at('TYPE_CHAM', 'field ' // name // ' of ' // p%name // &
                    ' is a ' // field_type_cham(f) // ', not ' // type_cham, st, &
                    STATUS_MODEL_ERROR)
                return
            end if
            out%field = f
            out%support => p
            out%model => null()
        end select
    end subroutine crea_extr

    !> The result of RESULTAT and the index of NUME_ORDRE or INST in it (PRECISION and
    !> CRITERE: Code_Aster's defaults 1e-6, RELATIF).
    subroutine result_instant(cmd, p, index, st)
        type(command_t), intent(in) :: cmd
        class(concept_t), pointer, intent(out) :: p
        integer(i4), intent(out) :: index
        type(status_t), intent(out) :: st
        real(dp) :: inst, precision
        integer(i4) :: nume_ordre
        character(len=:), allocatable :: criterion
        index = 0
        call cmd%get_concept('RESULTAT', p, st)
        if (st%failed()) return
        select type (p)
        class is (result_fields_t)
            if (cmd%has('INST')) then
                precision = 1.0e-6_dp
                criterion = 'RELATIF'
                if (cmd%has('PRECISION')) call cmd%get_real('PRECISION', precision, st)
                if (st%ok() .and. cmd%has('CRITERE')) call cmd%get_text('CRITERE', criterion, st)
                if (st%ok()) call cmd%get_real('INST', inst, st)
                if (st%failed()) return
                call result_find(p, index, st, inst=inst, precision=precision, &
                    criterion=criterion)
                if (st%failed()) call relocate(cmd, 'INST', st)
            else if (cmd%has('NUME_ORDRE')) then
                call cmd%get_int('NUME_ORDRE', nume_ordre, st)
                if (st%failed()) return
                call result_find(p, index, st, nume_ordre=nume_ordre)
                if (st%failed()) call relocate(cmd, 'NUME_ORDRE', st)
            else
                call cmd%error_at('RESULTAT', 'give NUME_ORDRE or INST (the instant to ' // &
                    'extract)', st, STATUS_MODEL_ERROR)
            end if
        class default
            call cmd%error_at('RESULTAT', 'expected a result, got ' // p%type_name(), st)
        end select
    end subroutine result_instant

    !> The nodes an occurrence names (TOUT, GROUP_MA: the nodes of its cells, GROUP_NO,
    !> NOEUD), as a mask over the mesh's nodes.
    !>  st : located at the keyword naming a group or node the mesh lacks
    subroutine selected_nodes(occ, mesh, mask, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        logical, allocatable, intent(out) :: mask(:)
        type(status_t), intent(out) :: st
        logical, allocatable :: cells(:)
        allocate (mask(mesh%n_nodes), source=occ%has('TOUT'))
        if (occ%has('GROUP_MA') .or. occ%has('MAILLE')) then
            call selected_cells(occ, mesh, cells, st)
            if (st%failed()) return
            call mark_nodes_of_cells(mesh, cells, mask)
        end if
        call mark_nodes(occ, 'GROUP_NO', 'NOEUD', mesh, mask, st)
    end subroutine selected_nodes

    !> The cells an occurrence names (TOUT, GROUP_MA, MAILLE), as a mask over the cells.
    !>  st : located at the keyword naming a group or cell the mesh lacks; GROUP_NO or NOEUD
    !>       alone (nodes do not name cells) is an error at that keyword
    subroutine selected_cells(occ, mesh, mask, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        logical, allocatable, intent(out) :: mask(:)
        type(status_t), intent(out) :: st
        allocate (mask(mesh%n_cells), source=occ%has('TOUT'))
        call mark_cells(occ, 'GROUP_MA', 'MAILLE', mesh, mask, st)
        if (st%failed()) return
        if (.not. (occ%has('TOUT') .or. occ%has('GROUP_MA') .or. occ%has('MAILLE'))) then
            if (occ%has('GROUP_NO')) then
                call occ%error_at('GROUP_NO', 'a field on cells is given on cells: use ' // &
                    'GROUP_MA or TOUT=''OUI''', st, STATUS_MODEL_ERROR)
            else if (occ%has('NOEUD')) then
                call occ%error_at('NOEUD', 'a field on cells is given on cells: use ' // &
                    'GROUP_MA or TOUT=''OUI''', st, STATUS_MODEL_ERROR)
            end if
        end if
    end subroutine selected_cells

    !> Index of `name` in `names`, 0 if absent.
    pure integer(i4) function position_of(names, name) result(k)
        type(string_t), intent(in) :: names(:)
        character(len=*), intent(in) :: name
        do k = 1, size(names, kind=i4)
            if (names(k)%s == name) return
        end do
        k = 0
    end function position_of

    !> A keyword OUI/NON as a logical.
    subroutine flag(kws, key, value, st)
        class(keyword_set_t), intent(in) :: kws
        character(len=*), intent(in) :: key
        logical, intent(out) :: value
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: text
        value = .false.
        call kws%get_text(key, text, st)
        if (st%ok()) value = text == 'OUI'
    end subroutine flag

end module crea_champ_command
