!> CREA_CHAMP's operations that build a field from other fields (Code_Aster U4.72.04):
!>   ASSE  assembles components of fields (ASSE: CHAM_GD, NOM_CMP renamed NOM_CMP_RESU, on
!>         TOUT / GROUP_MA / GROUP_NO, times COEF_R, added with CUMUL='OUI' or replacing);
!>         an element field takes its points from the fields assembled; PROL_ZERO='OUI'
!>         gives every cell of MODELE every component (zeros where none was assembled);
!>   COMB  sum of COEF_R x CHAM_GD over nodal fields (a node gets every component one of
!>         them has there);
!>   EVAL  evaluates a field of functions (CHAM_F, a *_F field) with, as parameters, the
!>         components of the CHAM_PARA fields at the same node (or cell, point and
!>         sub-point): X Y Z of a NOEU_GEOM_R, TEMP of a temperature, SIXX of a stress...
module crea_champ_combine
    use keyword_relocation, only: relocate => relocate_error
    use mesh_command_support, only: mark_cells, mark_nodes, mark_nodes_of_cells
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: string_t, to_text, to_upper
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t, concept_ref_t
    use mesh_types, only: mesh_t, find_cell_group, cells_of_group
    use model_types, only: model_t
    use function_concept, only: function_concept_t, param_binding_t
    use field_quantities, only: quantity_components, quantity_component_index, &
        components_text, quantity_is_function
    use field_types, only: field_t, component_set_t, field_init_nodes, field_init_cells, &
        field_define_cells, field_position, field_component, field_type_cham, FIELD_NOEU, FIELD_LOCATION_NAMES
    use field_concept, only: field_concept_t
    use field_layout, only: element_point_count
    use field_support, only: mesh_of_support, model_of_support
    use number_limits, only: product_fits, magnitude_fits
    implicit none
    private

    public :: crea_asse, crea_comb, crea_eval, component_sets_of, read_support

contains

    !> MAILLAGE or MODELE of a command: the field's support, its mesh and model (null for a
    !> maillage).
    subroutine read_support(cmd, out, mesh, model, st)
        type(command_t), intent(in) :: cmd
        type(field_concept_t), intent(inout) :: out
        type(mesh_t), pointer, intent(out) :: mesh
        type(model_t), pointer, intent(out) :: model
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        character(len=:), allocatable :: key
        mesh => null()
        model => null()
        key = 'MAILLAGE'
        if (cmd%has('MODELE')) key = 'MODELE'
        if (.not. cmd%has(key)) then
            call cmd%error_at('OPERATION', 'give MAILLAGE or MODELE (the mesh the field ' // &
                'lives on)', st, STATUS_MODEL_ERROR)
            return
        end if
        call cmd%get_concept(key, p, st)
        if (st%failed()) return
        call mesh_of_support(p, mesh, st)
        if (st%failed()) then
            call relocate(cmd, key, st)
            return
        end if
        call model_of_support(p, model)
        out%support => p
        if (key == 'MODELE') out%model => p
    end subroutine read_support

    !> Distinct patterns of assigned components, one set per pattern.
    !>  assigned : in, (n_cmp, n_cells)
    !>  cell_set : out, (n_cells) index into sets, 0 for a cell with none
    subroutine component_sets_of(assigned, cell_set, sets)
        logical, intent(in) :: assigned(:, :)
        integer(i4), allocatable, intent(out) :: cell_set(:)
        type(component_set_t), allocatable, intent(out) :: sets(:)
        type(component_set_t), allocatable :: bigger(:)
        logical, allocatable :: patterns(:, :), grown(:, :)
        integer(i4) :: c, k, n, j
        allocate (cell_set(size(assigned, 2)), source=0_i4)
        allocate (patterns(size(assigned, 1), 4), sets(4))
        n = 0
        do c = 1, size(assigned, 2, kind=i4)
            if (.not. any(assigned(:, c))) cycle
            k = 0
            do j = 1, n
                if (all(patterns(:, j) .eqv. assigned(:, c))) then
                    k = j
                    exit
                end if
            end do
            if (k == 0) then
                if (n == size(sets)) then
                    allocate (bigger(2 * n), grown(size(assigned, 1), 2 * n))
                    bigger(1:n) = sets(1:n)
                    grown(:, 1:n) = patterns(:, 1:n)
                    call move_alloc(bigger, sets)
                    call move_alloc(grown, patterns)
                end if
                n = n + 1
                patterns(:, n) = assigned(:, c)
                sets(n)%cmp = pack([(j, j = 1, size(assigned, 1, kind=i4))], assigned(:, c))
                k = n
            end if
            cell_set(c) = k
        end do
        sets = sets(1:n)
    end subroutine component_sets_of

    !> The field concept at `key` of `occ` (CHAM_GD, CHAM_F, CHAM_PARA).
    subroutine field_of(occ, key, f, st)
        class(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        type(field_concept_t), pointer, intent(out) :: f
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        f => null()
        call occ%get_concept(key, p, st)
        if (st%failed()) return
        select type (p)
        type is (field_concept_t)
            f => p
        class default
            call occ%error_at(key, 'expected a field (CREA_CHAMP), got ' // p%type_name(), st)
        end select
    end subroutine field_of

    !> OPERATION='ASSE' (module header).
    subroutine crea_asse(cmd, location, quantity, out, st)
        type(command_t), intent(in) :: cmd
        integer(i4), intent(in) :: location
        character(len=*), intent(in) :: quantity
        type(field_concept_t), intent(inout) :: out
        type(status_t), intent(out) :: st
        type(mesh_t), pointer :: mesh
        type(model_t), pointer :: model
        type(string_t), allocatable :: out_cmps(:)
        call read_support(cmd, out, mesh, model, st)
        if (st%ok()) call asse_components(cmd, quantity, out_cmps, st)
        if (st%failed()) return
        if (location == FIELD_NOEU) then
            call field_init_nodes(out%field, quantity, out_cmps, mesh%n_nodes, st)
            if (st%ok()) call asse_nodes(cmd, mesh, out%field, st)
        else
            call field_init_cells(out%field, location, quantity, out_cmps, mesh%n_cells, st)
            if (st%ok()) call asse_cells(cmd, mesh, model, out%field, st)
        end if
    end subroutine crea_asse

    !> The components an ASSE occurrence writes: NOM_CMP_RESU, else NOM_CMP, else every
    !> component of CHAM_GD; and the matching source components.
    subroutine occurrence_components(occ, src, from, to, st)
        type(keyword_set_t), intent(in) :: occ
        type(field_t), intent(in) :: src
        type(string_t), allocatable, intent(out) :: from(:), to(:)
        type(status_t), intent(out) :: st
        integer :: j
        if (occ%has('NOM_CMP')) then
            call occ%get_texts('NOM_CMP', from, st)
            if (st%failed()) return
            do j = 1, size(from)
                from(j)%s = to_upper(from(j)%s)
                if (field_component(src, from(j)%s) == 0) then
                    call occ%error_at('NOM_CMP', 'CHAM_GD has no component ' // from(j)%s // &
                        ' (it has ' // components_text(src%components) // ')', st, &
                        STATUS_MODEL_ERROR)
                    return
                end if
            end do
        else
            from = src%components
        end if
        if (occ%has('NOM_CMP_RESU')) then
            call occ%get_texts('NOM_CMP_RESU', to, st)
            if (st%failed()) return
            if (size(to) /= size(from)) then
                call occ%error_at('NOM_CMP_RESU', 'give one NOM_CMP_RESU per NOM_CMP (' // &
                    to_text(size(from)) // ')', st, STATUS_MODEL_ERROR)
                return
            end if
            do j = 1, size(to)
                to(j)%s = to_upper(to(j)%s)
            end do
        else
            to = from
        end if
    end subroutine occurrence_components

    !> The components of the assembled field, in the quantity's order.
    subroutine asse_components(cmd, quantity, cmps, st)
        type(command_t), intent(in) :: cmd
        character(len=*), intent(in) :: quantity
        type(string_t), allocatable, intent(out) :: cmps(:)
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: all(:), from(:), to(:)
        logical, allocatable :: used(:)
        type(field_concept_t), pointer :: src
        type(keyword_set_t) :: occ
        integer(i4) :: k, j, rank
        all = quantity_components(quantity, 999_i4)
        allocate (used(size(all)), source=.false.)
        do k = 1, cmd%count('ASSE')
            occ = cmd%occurrence('ASSE', k)
            call field_of(occ, 'CHAM_GD', src, st)
            if (st%ok()) call occurrence_components(occ, src%field, from, to, st)
            if (st%failed()) return
            do j = 1, size(to)
                rank = quantity_component_index(quantity, to(j)%s)
                if (rank == 0) then
                    call occ%error_at(trim(merge('NOM_CMP_RESU', 'NOM_CMP     ', &
                        occ%has('NOM_CMP_RESU'))), quantity // ' has no component ' // &
                        to(j)%s // ' (' // components_text(quantity_components(quantity)) // &
                        ')', st, STATUS_MODEL_ERROR)
                    return
                end if
                used(rank) = .true.
            end do
        end do
        cmps = pack(all, used)
    end subroutine asse_components

    !> ASSE into a NOEU field.
    subroutine asse_nodes(cmd, mesh, out, st)
        type(command_t), intent(in) :: cmd
        type(mesh_t), intent(in) :: mesh
        type(field_t), intent(inout) :: out
        type(status_t), intent(out) :: st
        type(field_concept_t), pointer :: src
        type(string_t), allocatable :: from(:), to(:)
        type(keyword_set_t) :: occ
        logical, allocatable :: selected(:)
        logical :: cumul, ok
        real(dp) :: coef
        integer(i4) :: k, j, a, b, n
        do k = 1, cmd%count('ASSE')
            occ = cmd%occurrence('ASSE', k)
            call field_of(occ, 'CHAM_GD', src, st)
            if (st%ok()) call occurrence_components(occ, src%field, from, to, st)
            if (st%ok()) call read_cumul(occ, cumul, coef, st)
            if (st%failed()) return
            if (src%field%location /= FIELD_NOEU .or. src%field%n_nodes /= mesh%n_nodes) then
                call occ%error_at('CHAM_GD', 'a NOEU field is assembled from NOEU fields ' // &
                    'of the same mesh (CHAM_GD is a ' // field_type_cham(src%field) // ')', &
                    st, STATUS_MODEL_ERROR)
                return
            end if
            call node_selection(occ, mesh, selected, st)
            if (st%failed()) return
            do j = 1, size(from)
                a = field_component(src%field, from(j)%s)
                b = field_component(out, to(j)%s)
                do n = 1, mesh%n_nodes
                    if (.not. (selected(n) .and. src%field%node_has(a, n))) cycle
                    call combine(out%node_values(b, n), coef, src%field%node_values(a, n), &
                        cumul .and. out%node_has(b, n), ok)
                    if (.not. ok) then
                        call overflow_at(occ, 'node number ' // to_text(n), st)
                        return
                    end if
                    out%node_has(b, n) = .true.
                end do
            end do
        end do
    end subroutine asse_nodes

    !> ASSE into an element field: points from the fields assembled (pass 1), values
    !> (pass 2).
    subroutine asse_cells(cmd, mesh, model, out, st)
        type(command_t), intent(in) :: cmd
        type(mesh_t), intent(in) :: mesh
        type(model_t), pointer, intent(in) :: model
        type(field_t), intent(inout) :: out
        type(status_t), intent(out) :: st
        type(field_concept_t), pointer :: src
        type(string_t), allocatable :: from(:), to(:)
        type(keyword_set_t) :: occ
        logical, allocatable :: selected(:), assigned(:, :)
        integer(i4), allocatable :: n_points(:), n_sub(:), cell_set(:)
        type(component_set_t), allocatable :: sets(:)
        logical :: cumul, prol_zero, ok
        real(dp) :: coef
        integer(i4) :: k, j, a, b, c, p, s, kind
        integer(i8) :: pa, pb
        character(len=:), allocatable :: text
        allocate (n_points(mesh%n_cells), n_sub(mesh%n_cells), source=0_i4)
        allocate (assigned(size(out%components), mesh%n_cells), source=.false.)
        do k = 1, cmd%count('ASSE')                  ! pass 1: the layout
            occ = cmd%occurrence('ASSE', k)
            call field_of(occ, 'CHAM_GD', src, st)
            if (st%ok()) call occurrence_components(occ, src%field, from, to, st)
            if (st%failed()) return
            if (src%field%location /= out%location .or. src%field%n_cells /= mesh%n_cells) &
                then
                call occ%error_at('CHAM_GD', 'a ' // FIELD_LOCATION_NAMES(out%location) // &
                    ' field is assembled from ' // FIELD_LOCATION_NAMES(out%location) // &
                    ' fields of the same mesh (CHAM_GD is a ' // field_type_cham(src%field) // &
                    ')', st, STATUS_MODEL_ERROR)
                return
            end if
            call cell_selection(occ, mesh, selected, st)
            if (st%failed()) return
            do c = 1, mesh%n_cells
                if (.not. selected(c) .or. src%field%n_points(c) == 0) cycle
                if (n_points(c) > 0 .and. (n_points(c) /= src%field%n_points(c) .or. &
                    n_sub(c) /= src%field%n_subpoints(c))) then
                    call occ%error_at('CHAM_GD', 'the fields assembled have different ' // &
                        'points on cell number ' // to_text(c), st, STATUS_MODEL_ERROR)
                    return
                end if
                n_points(c) = src%field%n_points(c)
                n_sub(c) = src%field%n_subpoints(c)
                do j = 1, size(from)
                    a = field_component(src%field, from(j)%s)
                    if (field_position(src%field, c, 1_i4, 1_i4, a) > 0) &
                        assigned(field_component(out, to(j)%s), c) = .true.
                end do
            end do
        end do
        prol_zero = .false.
        if (cmd%has('PROL_ZERO')) then
            call cmd%get_text('PROL_ZERO', text, st)
            if (st%failed()) return
            prol_zero = text == 'OUI'
        end if
        if (prol_zero) then
            do c = 1, mesh%n_cells
                if (n_points(c) == 0 .and. associated(model)) then
                    kind = model%element(c)
                    n_points(c) = element_point_count(kind, mesh%cell_type(c), out%location)
                    n_sub(c) = 1
                end if
                if (n_points(c) > 0) assigned(:, c) = .true.
            end do
        end if
        where (.not. any(assigned, dim=1)) n_points = 0
        call component_sets_of(assigned, cell_set, sets)
        call field_define_cells(out, n_points, n_sub, cell_set, sets, st)
        if (st%failed()) return
        do k = 1, cmd%count('ASSE')                  ! pass 2: the values
            occ = cmd%occurrence('ASSE', k)
            call field_of(occ, 'CHAM_GD', src, st)
            if (st%ok()) call occurrence_components(occ, src%field, from, to, st)
            if (st%ok()) call read_cumul(occ, cumul, coef, st)
            if (st%ok()) call cell_selection(occ, mesh, selected, st)
            if (st%failed()) return
            do c = 1, mesh%n_cells
                if (.not. selected(c) .or. src%field%n_points(c) == 0) cycle
                do j = 1, size(from)
                    a = field_component(src%field, from(j)%s)
                    b = field_component(out, to(j)%s)
                    do p = 1, n_points(c)
                        do s = 1, n_sub(c)
                            pa = field_position(src%field, c, p, s, a)
                            pb = field_position(out, c, p, s, b)
                            if (pa == 0 .or. pb == 0) cycle
                            call combine(out%values(pb), coef, src%field%values(pa), cumul, ok)
                            if (.not. ok) then
                                call overflow_at(occ, 'cell number ' // to_text(c), st)
                                return
                            end if
                        end do
                    end do
                end do
            end do
        end do
    end subroutine asse_cells

    !> target = coef * value (+ target when add), unless the result would be beyond
    !> 2**MAX_BINARY_EXPONENT (number_limits): then ok is false and target is unchanged.
    elemental subroutine combine(target, coef, value, add, ok)
        real(dp), intent(inout) :: target
        real(dp), intent(in) :: coef, value
        logical, intent(in) :: add
        logical, intent(out) :: ok
        real(dp) :: term
        ok = product_fits(coef, value)
        if (.not. ok) return
        term = coef * value
        if (add) then
            ok = magnitude_fits(target)
            if (.not. ok) return
            term = target + term
        end if
        ok = magnitude_fits(term)
        if (ok) target = term
    end subroutine combine

    !> The error of a combination beyond double precision, at COEF_R of the occurrence.
    subroutine overflow_at(occ, where, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: where
        type(status_t), intent(out) :: st
        call occ%error_at('COEF_R', 'COEF_R times the field''s value at ' // where // &
            ' is beyond the range parasol computes in (|x| < 2**1000, about 1e301)', st, &
            STATUS_MODEL_ERROR)
    end subroutine overflow_at

    !> CUMUL (OUI: added to what is there) and COEF_R (default 1).
    subroutine read_cumul(occ, cumul, coef, st)
        type(keyword_set_t), intent(in) :: occ
        logical, intent(out) :: cumul
        real(dp), intent(out) :: coef
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: text
        cumul = .false.
        coef = 1.0_dp
        if (occ%has('CUMUL')) then
            call occ%get_text('CUMUL', text, st)
            if (st%failed()) return
            cumul = text == 'OUI'
        end if
        if (occ%has('COEF_R')) call occ%get_real('COEF_R', coef, st)
    end subroutine read_cumul

    !> Nodes of TOUT / GROUP_MA / GROUP_NO of an ASSE occurrence.
    subroutine node_selection(occ, mesh, mask, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        logical, allocatable, intent(out) :: mask(:)
        type(status_t), intent(out) :: st
        logical, allocatable :: cells(:)
        allocate (mask(mesh%n_nodes), source=occ%has('TOUT'))
        call mark_nodes(occ, 'GROUP_NO', 'NOEUD', mesh, mask, st)
        if (st%failed()) return
        allocate (cells(mesh%n_cells), source=.false.)
        call mark_cells(occ, 'GROUP_MA', 'MAILLE', mesh, cells, st)
        if (st%failed()) return
        call mark_nodes_of_cells(mesh, cells, mask)
    end subroutine node_selection

    !> Cells of TOUT / GROUP_MA of an ASSE occurrence.
    subroutine cell_selection(occ, mesh, mask, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        logical, allocatable, intent(out) :: mask(:)
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        integer(i4) :: k, g
        allocate (mask(mesh%n_cells), source=occ%has('TOUT'))
        if (occ%has('GROUP_MA')) then
            call occ%get_texts('GROUP_MA', names, st)
            if (st%failed()) return
            do k = 1, size(names)
                g = find_cell_group(mesh, names(k)%s, st)
                if (st%failed()) then
                    call relocate(occ, 'GROUP_MA', st)
                    return
                end if
                mask(cells_of_group(mesh, g)) = .true.
            end do
        end if
        if (occ%has('GROUP_NO') .and. .not. (occ%has('TOUT') .or. occ%has('GROUP_MA'))) &
            call occ%error_at('GROUP_NO', 'an element field is assembled on cells: use ' // &
                'GROUP_MA or TOUT=''OUI''', st, STATUS_MODEL_ERROR)
    end subroutine cell_selection

    !> OPERATION='COMB': sum of COEF_R x CHAM_GD (NOEU fields).
    subroutine crea_comb(cmd, location, quantity, out, st)
        type(command_t), intent(in) :: cmd
        integer(i4), intent(in) :: location
        character(len=*), intent(in) :: quantity
        type(field_concept_t), intent(inout) :: out
        type(status_t), intent(out) :: st
        type(field_concept_t), pointer :: src
        type(keyword_set_t) :: occ
        type(string_t), allocatable :: all(:)
        logical, allocatable :: used(:)
        real(dp) :: coef
        logical :: ok
        integer(i4) :: k, j, a, rank, n_nodes, n
        if (location /= FIELD_NOEU) then
            call cmd%error_at('TYPE_CHAM', 'COMB combines nodal fields (NOEU_*), not ' // &
                FIELD_LOCATION_NAMES(location), st, STATUS_MODEL_ERROR)
            return
        end if
        all = quantity_components(quantity)
        allocate (used(size(all)), source=.false.)
        do k = 1, cmd%count('COMB')
            occ = cmd%occurrence('COMB', k)
            call field_of(occ, 'CHAM_GD', src, st)
            if (st%failed()) return
            if (src%field%location /= FIELD_NOEU .or. src%field%quantity /= quantity) then
                call occ%error_at('CHAM_GD', 'COMB makes a NOEU_' // quantity // ' from ' // &
                    'NOEU_' // quantity // ' fields (CHAM_GD is a ' // &
                    field_type_cham(src%field) // ')', st, STATUS_MODEL_ERROR)
                return
            end if
            if (k > 1 .and. src%field%n_nodes /= n_nodes) then
                call occ%error_at('CHAM_GD', 'the fields combined live on different ' // &
                    'meshes', st, STATUS_MODEL_ERROR)
                return
            end if
            if (k == 1) then
                out%support => src%support
                n_nodes = src%field%n_nodes
            end if
            do j = 1, size(src%field%components)
                rank = quantity_component_index(quantity, src%field%components(j)%s)
                used(rank) = .true.
            end do
        end do
        call field_init_nodes(out%field, quantity, pack(all, used), n_nodes, st)
        if (st%failed()) return
        do k = 1, cmd%count('COMB')
            occ = cmd%occurrence('COMB', k)
            call field_of(occ, 'CHAM_GD', src, st)
            if (st%ok()) call occ%get_real('COEF_R', coef, st)
            if (st%failed()) return
            do j = 1, size(src%field%components)
                a = field_component(out%field, src%field%components(j)%s)
                do n = 1, n_nodes
                    if (.not. src%field%node_has(j, n)) cycle
                    call combine(out%field%node_values(a, n), coef, &
                        src%field%node_values(j, n), .true., ok)
                    if (.not. ok) then
                        call overflow_at(occ, 'node number ' // to_text(n), st)
                        return
                    end if
                    out%field%node_has(a, n) = .true.
                end do
            end do
        end do
    end subroutine crea_comb

    !> OPERATION='EVAL' (module header).
    subroutine crea_eval(cmd, location, quantity, out, st)
        type(command_t), intent(in) :: cmd
        integer(i4), intent(in) :: location
        character(len=*), intent(in) :: quantity
        type(field_concept_t), intent(inout) :: out
        type(status_t), intent(out) :: st
        type(field_concept_t), pointer :: fun
        type(concept_ref_t), allocatable :: refs(:)
        type(string_t), allocatable :: names(:)
        type(param_binding_t), allocatable :: bindings(:)
        character(len=:), allocatable :: words(:)
        integer(i4) :: k, j
        call field_of(cmd, 'CHAM_F', fun, st)
        if (st%ok()) call cmd%get_concepts('CHAM_PARA', refs, st)
        if (st%failed()) return
        if (.not. quantity_is_function(fun%field%quantity)) then
            call cmd%error_at('CHAM_F', 'CHAM_F must be a field of functions (*_F), not a ' // &
                field_type_cham(fun%field), st, STATUS_MODEL_ERROR)
            return
        end if
        if (fun%field%location /= location) then
            call cmd%error_at('TYPE_CHAM', 'EVAL keeps the location of CHAM_F (' // &
                field_type_cham(fun%field) // '): TYPE_CHAM must start with ' // &
                FIELD_LOCATION_NAMES(fun%field%location), st, STATUS_MODEL_ERROR)
            return
        end if
        do j = 1, size(fun%field%components)
            if (quantity_component_index(quantity, fun%field%components(j)%s) == 0) then
                call cmd%error_at('TYPE_CHAM', quantity // ' has no component ' // &
                    fun%field%components(j)%s // ' of CHAM_F', st, STATUS_MODEL_ERROR)
                return
            end if
        end do
        allocate (names(0))
        do k = 1, size(refs)
            select type (p => refs(k)%ptr)
            type is (field_concept_t)
                if (p%field%location /= location .or. (location == FIELD_NOEU .and. &
                    p%field%n_nodes /= fun%field%n_nodes) .or. (location /= FIELD_NOEU .and. &
                    p%field%n_cells /= fun%field%n_cells)) then
                    call cmd%error_at('CHAM_PARA', 'the parameter fields must be ' // &
                        FIELD_LOCATION_NAMES(location) // ' fields of the mesh of CHAM_F ' // &
                        '(field ' // to_text(k) // ' is a ' // field_type_cham(p%field) // ')', &
                        st, STATUS_MODEL_ERROR)
                    return
                end if
                do j = 1, size(p%field%components)
                    if (position_of(names, p%field%components(j)%s) == 0) &
                        call append_name(names, p%field%components(j)%s)
                end do
            class default
                call cmd%error_at('CHAM_PARA', 'expected fields (CREA_CHAMP), got ' // &
                    p%type_name(), st)
                return
            end select
        end do
        allocate (bindings(size(fun%field%functions)))
        allocate (character(len=max(1, maxval([(len(names(j)%s), j = 1, size(names)), 1]))) :: &
            words(size(names)))
        do j = 1, size(names)
            words(j) = names(j)%s
        end do
        do k = 1, size(fun%field%functions)
            call fun%field%functions(k)%f%bind(words, bindings(k))
        end do
        out%support => fun%support
        out%model => fun%model
        if (location == FIELD_NOEU) then
            call eval_nodes(cmd, fun%field, refs, names, bindings, quantity, out%field, st)
        else
            call eval_cells(cmd, fun%field, refs, names, bindings, quantity, out%field, st)
        end if
    end subroutine crea_eval

    !> EVAL of a NOEU field of functions.
    subroutine eval_nodes(cmd, fun, refs, names, bindings, quantity, out, st)
        type(command_t), intent(in) :: cmd
        type(field_t), intent(in) :: fun
        type(concept_ref_t), intent(in) :: refs(:)
        type(string_t), intent(in) :: names(:)
        type(param_binding_t), intent(in) :: bindings(:)
        character(len=*), intent(in) :: quantity
        type(field_t), intent(inout) :: out
        type(status_t), intent(out) :: st
        real(dp) :: args(size(names))
        logical :: have(size(names))
        integer(i4) :: n, k, f
        call field_init_nodes(out, quantity, fun%components, fun%n_nodes, st)
        if (st%failed()) return
        do n = 1, fun%n_nodes
            if (.not. any(fun%node_has(:, n))) cycle
            call node_arguments(refs, names, n, args, have)
            do k = 1, size(fun%components, kind=i4)
                if (.not. fun%node_has(k, n)) cycle
                f = nint(fun%node_values(k, n))
                call evaluate(cmd, fun, f, bindings(f), names, args, have, &
                    'node number ' // to_text(n), out%node_values(k, n), st)
                if (st%failed()) return
                out%node_has(k, n) = .true.
            end do
        end do
    end subroutine eval_nodes

    !> The parameter values the CHAM_PARA fields give at node n (have: which exist there).
    subroutine node_arguments(refs, names, n, args, have)
        type(concept_ref_t), intent(in) :: refs(:)
        type(string_t), intent(in) :: names(:)
        integer(i4), intent(in) :: n
        real(dp), intent(out) :: args(:)
        logical, intent(out) :: have(:)
        integer(i4) :: k, j, a
        args = 0.0_dp
        have = .false.
        do k = 1, size(refs)
            select type (p => refs(k)%ptr)
            type is (field_concept_t)
                do j = 1, size(p%field%components, kind=i4)
                    if (.not. p%field%node_has(j, n)) cycle
                    a = position_of(names, p%field%components(j)%s)
                    args(a) = p%field%node_values(j, n)
                    have(a) = .true.
                end do
            end select
        end do
    end subroutine node_arguments

    !> EVAL of an element field of functions: the layout of CHAM_F, parameters at the same
    !> cell, point and sub-point.
    subroutine eval_cells(cmd, fun, refs, names, bindings, quantity, out, st)
        type(command_t), intent(in) :: cmd
        type(field_t), intent(in) :: fun
        type(concept_ref_t), intent(in) :: refs(:)
        type(string_t), intent(in) :: names(:)
        type(param_binding_t), intent(in) :: bindings(:)
        character(len=*), intent(in) :: quantity
        type(field_t), intent(inout) :: out
        type(status_t), intent(out) :: st
        real(dp) :: args(size(names))
        logical :: have(size(names))
        integer(i4) :: c, p, s, j, k, f, a, r
        integer(i8) :: pos, q
        call field_init_cells(out, fun%location, quantity, fun%components, fun%n_cells, st)
        if (st%ok()) call field_define_cells(out, fun%n_points, fun%n_subpoints, &
            fun%cell_set, fun%sets, st)
        if (st%failed()) return
        do c = 1, fun%n_cells
            if (fun%n_points(c) == 0) cycle
            do p = 1, fun%n_points(c)
                do s = 1, fun%n_subpoints(c)
                    args = 0.0_dp
                    have = .false.
                    do r = 1, size(refs)
                        select type (para => refs(r)%ptr)
                        type is (field_concept_t)
                            do j = 1, size(para%field%components, kind=i4)
                                q = field_position(para%field, c, p, s, j)
                                if (q == 0) cycle
                                a = position_of(names, para%field%components(j)%s)
                                args(a) = para%field%values(q)
                                have(a) = .true.
                            end do
                        end select
                    end do
                    do k = 1, size(fun%components, kind=i4)
                        pos = field_position(fun, c, p, s, k)
                        if (pos == 0) cycle
                        f = nint(fun%values(pos))
                        call evaluate(cmd, fun, f, bindings(f), names, args, have, &
                            'cell number ' // to_text(c) // ', point ' // to_text(p), &
                            out%values(pos), st)
                        if (st%failed()) return
                    end do
                end do
            end do
        end do
    end subroutine eval_cells

    !> Evaluates function f of the field with the parameters present; a parameter the
    !> function needs and no CHAM_PARA gives there is an error at CHAM_PARA.
    subroutine evaluate(cmd, fun, f, binding, names, args, have, where, y, st)
        type(command_t), intent(in) :: cmd
        type(field_t), intent(in) :: fun
        integer(i4), intent(in) :: f
        type(param_binding_t), intent(in) :: binding
        type(string_t), intent(in) :: names(:)
        real(dp), intent(in) :: args(:)
        logical, intent(in) :: have(:)
        character(len=*), intent(in) :: where
        real(dp), intent(out) :: y
        type(status_t), intent(out) :: st
        integer :: i
        y = 0.0_dp
        do i = 1, size(binding%slot)
            if (binding%slot(i) == 0) then
                call cmd%error_at('CHAM_PARA', 'function ' // fun%functions(f)%f%name // &
                    ' needs parameter ' // binding%names(i)%s // ', which no CHAM_PARA ' // &
                    'field has (they have ' // components_text(names) // ')', st, &
                    STATUS_MODEL_ERROR)
                return
            end if
            if (.not. have(binding%slot(i))) then
                call cmd%error_at('CHAM_PARA', 'function ' // fun%functions(f)%f%name // &
                    ' needs parameter ' // binding%names(i)%s // ', which the CHAM_PARA ' // &
                    'fields do not have at ' // where, st, STATUS_MODEL_ERROR)
                return
            end if
        end do
        call fun%functions(f)%f%evaluate(binding, args, y, st)
        if (st%failed()) then
            st%message = 'function ' // fun%functions(f)%f%name // ' at ' // where // ': ' // &
                st%message
            call relocate(cmd, 'CHAM_F', st)
        end if
    end subroutine evaluate

    !> Appends a name (moving the others: no temporary array of strings).
    subroutine append_name(names, name)
        type(string_t), allocatable, intent(inout) :: names(:)
        character(len=*), intent(in) :: name
        type(string_t), allocatable :: bigger(:)
        integer :: k
        allocate (bigger(size(names) + 1))
        do k = 1, size(names)
            call move_alloc(names(k)%s, bigger(k)%s)
        end do
        bigger(size(bigger))%s = name
        call move_alloc(bigger, names)
    end subroutine append_name

    !> Index of `name` in `names`, 0 if absent.
    pure integer(i4) function position_of(names, name) result(k)
        type(string_t), intent(in) :: names(:)
        character(len=*), intent(in) :: name
        do k = 1, size(names, kind=i4)
            if (names(k)%s == name) return
        end do
        k = 0
    end function position_of

end module crea_champ_combine
