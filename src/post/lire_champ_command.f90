!> LIRE_CHAMP (Code_Aster U7.02.02, code_aster/Cata/Commands/lire_champ.py), FORMAT='MED':
!> a field of a MED file (NOM_MED) as a field concept of TYPE_CHAM on MAILLAGE (doc/fields.md,
!> "LIRE_CHAMP") -- the fields IMPR_RESU writes, read back:
!>  NOEU  the values on the nodes (MED_NODE), through the profile of each part;
!>  ELGA  the values on the cells' integration points (MED_CELL): per cell type, the points
!>        of the element family with as many points (MODELE; field_layout) and, when the
!>        part has a multiple of them, as many sub-points (plate layers, written as points
!>        by IMPR_RESU, the sub-points of each point in turn);
!>  ELNO  the values on the cells' nodes (MED_NODE_ELEMENT), or on MED_CELL integration points
!>        at the nodes with sub-points (IMPR_RESU's layout of ELNO fields with layers);
!>  ELEM, CART  one value set per cell (sub-points likewise);
!> the computation step by NUME_PT or NUME_ORDRE (the step's numbers) or INST (its time,
!> CRITERE / PRECISION), the only or first step by default; components NOM_CMP_IDEM (the
!> file's names) or NOM_CMP renaming NOM_CMP_MED; PROL_ZERO='OUI' gives every node (every
!> cell with an element of MODELE) the components, 0 where the file has none. Cells are
!> matched to the file's by type and rank within the type (the order IMPR_RESU and
!> LIRE_MAILLAGE use), so MAILLAGE must be the mesh the file's field lies on.
module lire_champ_command
    use keyword_relocation, only: relocate => relocate_error
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_IO_ERROR
    use strings, only: string_t, to_text, to_upper, real_e13
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, CELL_TYPE_NODES, CELL_TYPE_ORDER, N_CELL_TYPES
    use mesh_concept, only: mesh_concept_t
    use model_types, only: model_t
    use model_concept, only: model_concept_t
    use med_file, only: med_file_t, med_open, med_close, med_field_count, med_field_info, &
        med_field_steps, med_field_part_count, med_field_part_info, med_read_entity_values, &
        med_read_profile, MED_READ, MED_SNAME_LEN, MED_ENTITY_CELL, MED_ENTITY_NODE, &
        MED_ENTITY_NODE_ELEMENT
    use field_types, only: field_t, component_set_t, field_init_nodes, field_init_cells, &
        field_define_cells, parse_type_cham, FIELD_NOEU, FIELD_ELGA, FIELD_ELNO, FIELD_ELEM, &
        FIELD_CART
    use field_quantities, only: quantity_component_index
    use field_concept, only: field_concept_t
    use field_layout, only: element_point_count
    implicit none
    private

    !> MED cell type codes in Code_Aster's type order (CELL_TYPE_ORDER; med.h).
    integer(i4), parameter :: MED_CODES(N_CELL_TYPES) = [1, 102, 103, 203, 206, 204, 208, 209]
    !> Code_Aster's default UNITE of LIRE_CHAMP.
    integer(i4), parameter :: DEFAULT_UNIT = 81

    public :: run_lire_champ

contains

    !> Handler of LIRE_CHAMP.
    !>  st : located errors: the unit not bound, the field or step not in the file, a
    !>       component of the file not in the quantity, a part whose points match no
    !>       element family, a MED read error
    subroutine run_lire_champ(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p, pm
        type(mesh_t), pointer :: mesh
        type(model_t), pointer :: model
        type(field_concept_t), allocatable :: out
        type(med_file_t) :: file
        type(status_t) :: closing
        character(len=:), allocatable :: path, name, type_cham, quantity, key
        character(len=MED_SNAME_LEN), allocatable :: med_cmps(:)
        type(string_t), allocatable :: names(:)
        integer(i4), allocatable :: map(:)
        integer(i4) :: unit, location, numdt, numit
        real(dp) :: time
        if (ctx%checking) then
            allocate (field_concept_t :: result)
            return
        end if
        model => null()
        call cmd%get_concept('MAILLAGE', p, st)
        if (st%failed()) return
        select type (p)
        type is (mesh_concept_t)
            mesh => p%mesh
        class default
            call cmd%error_at('MAILLAGE', 'expected a mesh, got ' // p%type_name(), st)
            return
        end select
        call cmd%get_text('TYPE_CHAM', type_cham, st)
        if (st%ok()) call parse_type_cham(type_cham, location, quantity, st)
        if (st%failed()) then
            call relocate(cmd, 'TYPE_CHAM', st)
            return
        end if
        if (location /= FIELD_NOEU .and. location /= FIELD_CART) then
            if (.not. cmd%has('MODELE')) then
                call cmd%error_at('MODELE', 'an element field (' // type_cham // ') needs ' // &
                    'MODELE', st, STATUS_MODEL_ERROR)
                return
            end if
            call cmd%get_concept('MODELE', pm, st)
            if (st%failed()) return
            select type (pm)
            type is (model_concept_t)
                model => pm%model
            end select
        end if
        unit = DEFAULT_UNIT
        if (cmd%given('UNITE')) call cmd%get_int('UNITE', unit, st)
        if (st%ok()) call ctx%unit_path(unit, 'MED', path, st)
        if (st%ok()) call cmd%get_text('NOM_MED', name, st)
        if (st%failed()) then
            call relocate(cmd, 'UNITE', st)
            return
        end if
        call med_open(file, path, MED_READ, st)
        if (st%failed()) then
            call relocate(cmd, 'UNITE', st)
            return
        end if
        call find_field(file, name, med_cmps, st)
        if (st%ok()) call read_step(cmd, file, name, numdt, numit, time, st)
        if (st%ok()) call component_map(cmd, med_cmps, quantity, names, map, st)
        if (st%ok()) then
            allocate (out)
            out%support => p
            if (associated(model)) out%model => pm
            if (location == FIELD_NOEU) then
                call read_nodes(file, name, numdt, numit, mesh, quantity, names, map, &
                    size(med_cmps, kind=i4), cmd_prol_zero(cmd), out%field, st)
            else
                call read_cells(file, name, numdt, numit, mesh, model, location, quantity, &
                    names, map, size(med_cmps, kind=i4), cmd_prol_zero(cmd), out%field, st)
            end if
        end if
        call med_close(file, closing)
        if (st%failed()) then
            key = 'NOM_MED'
            if (allocated(st%keyword)) key = st%keyword
            call relocate(cmd, key, st)
            return
        end if
        call ctx%write_mess('    LIRE_CHAMP: ' // name // ' (' // type_cham // ') step (' // &
            to_text(numdt) // ', ' // to_text(numit) // ') INST ' // real_e13(time) // &
            ' from ' // path)
        call move_alloc(out, result)
    end subroutine run_lire_champ

    logical function cmd_prol_zero(cmd)
        type(command_t), intent(in) :: cmd
        character(len=:), allocatable :: text
        type(status_t) :: st
        cmd_prol_zero = .false.
        if (.not. cmd%has('PROL_ZERO')) return
        call cmd%get_text('PROL_ZERO', text, st)
        cmd_prol_zero = text == 'OUI'
    end function cmd_prol_zero

    ! The file's field `name` and its components.
    subroutine find_field(file, name, cmps, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: name
        character(len=MED_SNAME_LEN), allocatable, intent(out) :: cmps(:)
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: found, mesh, all
        integer(i4) :: n, k
        n = med_field_count(file, st)
        if (st%failed()) return
        all = ''
        do k = 1, n
            call med_field_info(file, k, found, mesh, cmps, st)
            if (st%failed()) return
            if (found == name) return
            if (k <= 10) all = all // ' ' // found
        end do
        if (n == 0) all = ' none'
        call set_error(st, STATUS_MODEL_ERROR, 'the file has no field ' // name // ' (it has' &
            // all // ')')
    end subroutine find_field

    ! The step asked for: NUME_PT / NUME_ORDRE (its numbers), INST (its time), or the first.
    subroutine read_step(cmd, file, name, numdt, numit, time, st)
        type(command_t), intent(in) :: cmd
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: name
        integer(i4), intent(out) :: numdt, numit
        real(dp), intent(out) :: time
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: dts(:), its(:), wanted(:)
        real(dp), allocatable :: times(:)
        real(dp), allocatable :: insts(:)
        real(dp) :: precision
        character(len=:), allocatable :: criterion, key
        integer(i4) :: k, found
        call med_field_steps(file, name, dts, its, times, st)
        if (st%failed()) return
        if (size(dts) == 0) then
            call set_error(st, STATUS_MODEL_ERROR, 'field ' // name // ' has no step')
            return
        end if
        found = 1
        key = ''
        if (cmd%has('NUME_PT')) key = 'NUME_PT'
        if (cmd%has('NUME_ORDRE')) key = 'NUME_ORDRE'
        if (len(key) > 0) then
            call cmd%get_ints(key, wanted, st)
            if (st%failed()) return
            found = findloc(dts, wanted(1), dim=1)
        else if (cmd%has('INST')) then
            key = 'INST'
            call cmd%get_reals('INST', insts, st)
            precision = 1.0e-6_dp
            criterion = 'RELATIF'
            if (st%ok() .and. cmd%has('PRECISION')) call cmd%get_real('PRECISION', precision, st)
            if (st%ok() .and. cmd%has('CRITERE')) call cmd%get_text('CRITERE', criterion, st)
            if (st%failed()) return
            found = 0
            do k = 1, size(times, kind=i4)
                if (criterion == 'ABSOLU' .or. .not. abs(insts(1)) > 0.0_dp) then
                    if (abs(times(k) - insts(1)) <= precision) found = k
                else
                    if (abs(times(k) - insts(1)) <= precision * abs(insts(1))) found = k
                end if
            end do
        end if
        if (found == 0) then
            call set_error(st, STATUS_MODEL_ERROR, key // ': field ' // name // ' has no ' // &
                'such step (it has ' // to_text(size(dts)) // ', numbers ' // &
                to_text(dts(1)) // ' to ' // to_text(dts(size(dts))) // ')')
            st%keyword = key
            return
        end if
        numdt = dts(found)
        numit = its(found)
        time = times(found)
    end subroutine read_step

    ! The field's components (NOM_CMP, or the file's with NOM_CMP_IDEM) and, for each, its
    ! column in the file (map(k) = index into the file's components).
    subroutine component_map(cmd, med_cmps, quantity, names, map, st)
        type(command_t), intent(in) :: cmd
        character(len=MED_SNAME_LEN), intent(in) :: med_cmps(:)
        character(len=*), intent(in) :: quantity
        type(string_t), allocatable, intent(out) :: names(:)
        integer(i4), allocatable, intent(out) :: map(:)
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: file_names(:)
        integer(i4) :: k, j
        if (cmd%has('NOM_CMP')) then
            call cmd%get_texts('NOM_CMP', names, st)
            if (st%ok()) call cmd%get_texts('NOM_CMP_MED', file_names, st)
            if (st%failed()) return
            if (size(file_names) /= size(names)) then
                call cmd%error_at('NOM_CMP_MED', 'NOM_CMP_MED names ' // &
                    to_text(size(file_names)) // ' component(s), NOM_CMP ' // &
                    to_text(size(names)), st, STATUS_MODEL_ERROR)
                return
            end if
        else
            allocate (names(size(med_cmps)), file_names(size(med_cmps)))
            do k = 1, size(med_cmps)
                names(k)%s = trim(med_cmps(k))
                file_names(k)%s = trim(med_cmps(k))
            end do
        end if
        allocate (map(size(names)))
        do k = 1, size(names, kind=i4)
            names(k)%s = to_upper(names(k)%s)
            map(k) = 0
            do j = 1, size(med_cmps, kind=i4)
                if (trim(med_cmps(j)) == to_upper(file_names(k)%s)) map(k) = j
            end do
            if (map(k) == 0) then
                call set_error(st, STATUS_MODEL_ERROR, 'the file''s field has no component ' &
                    // file_names(k)%s)
                st%keyword = trim(merge('NOM_CMP_MED ', 'NOM_MED     ', cmd%has('NOM_CMP')))
                return
            end if
            if (quantity_component_index(quantity, names(k)%s) == 0) then
                call set_error(st, STATUS_MODEL_ERROR, names(k)%s // ' is no component of ' &
                    // quantity)
                st%keyword = trim(merge('NOM_CMP', 'NOM_MED', cmd%has('NOM_CMP')))
                return
            end if
        end do
    end subroutine component_map

    ! NOEU: the parts on MED_NODE.
    subroutine read_nodes(file, name, numdt, numit, mesh, quantity, names, map, n_file, zero, &
                          f, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: name, quantity
        integer(i4), intent(in) :: numdt, numit, map(:), n_file
        type(mesh_t), intent(in) :: mesh
        type(string_t), intent(in) :: names(:)
        logical, intent(in) :: zero
        type(field_t), intent(out) :: f
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: profile, localization
        integer(i4), allocatable :: nodes(:)
        real(dp), allocatable :: values(:)
        integer(i4) :: parts, k, n_points, n_entities, e, j
        call field_init_nodes(f, quantity, names, mesh%n_nodes, st)
        if (st%failed()) return
        if (zero) f%node_has = .true.
        parts = med_field_part_count(file, name, numdt, numit, MED_ENTITY_NODE, 0_i4, st)
        if (st%failed()) return
        do k = 1, parts
            call med_field_part_info(file, name, numdt, numit, MED_ENTITY_NODE, 0_i4, k, &
                profile, localization, n_points, n_entities, st)
            if (st%failed()) return
            call entities_of(file, profile, n_entities, mesh%n_nodes, nodes, st)
            if (st%failed()) return
            allocate (values(int(n_entities, i8) * n_file * max(n_points, 1_i4)))
            call med_read_entity_values(file, name, numdt, numit, MED_ENTITY_NODE, 0_i4, &
                profile, values, st)
            if (st%failed()) return
            do e = 1, n_entities
                do j = 1, size(map, kind=i4)
                    f%node_values(j, nodes(e)) = values((e - 1) * n_file + map(j))
                    f%node_has(j, nodes(e)) = .true.
                end do
            end do
            deallocate (values)
        end do
    end subroutine read_nodes

    ! ELGA / ELNO / ELEM / CART: per cell type, the parts on the cells (module header).
    subroutine read_cells(file, name, numdt, numit, mesh, model, location, quantity, names, &
                          map, n_file, zero, f, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: name, quantity
        integer(i4), intent(in) :: numdt, numit, location, map(:), n_file
        type(mesh_t), intent(in) :: mesh
        type(model_t), pointer, intent(in) :: model
        type(string_t), intent(in) :: names(:)
        logical, intent(in) :: zero
        type(field_t), intent(out) :: f
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: n_points(:), n_sub(:), cell_set(:), rank_cell(:, :)
        integer(i4), allocatable :: counts(:), cells(:)
        type(component_set_t) :: sets(1)
        integer(i4) :: t, c, k, e, np, ns, j, p, n_cmp, entity, total, pass
        integer(i8) :: base
        n_cmp = size(names, kind=i4)
        call field_init_cells(f, location, quantity, names, mesh%n_cells, st)
        if (st%failed()) return
        allocate (n_points(mesh%n_cells), n_sub(mesh%n_cells), cell_set(mesh%n_cells), &
            source=0_i4)
        ! cells by type and rank within the type
        allocate (counts(N_CELL_TYPES), source=0_i4)
        allocate (rank_cell(N_CELL_TYPES, mesh%n_cells), source=0_i4)
        do c = 1, mesh%n_cells
            t = findloc(CELL_TYPE_ORDER, mesh%cell_type(c), dim=1)
            counts(t) = counts(t) + 1
            rank_cell(t, counts(t)) = c
        end do
        do pass = 1, 2               ! the layout, then (field_define_cells) the values
            do t = 1, N_CELL_TYPES
                if (counts(t) == 0) cycle
                do entity = MED_ENTITY_CELL, MED_ENTITY_NODE_ELEMENT, MED_ENTITY_NODE_ELEMENT
                    total = med_field_part_count(file, name, numdt, numit, entity, &
                        MED_CODES(t), st)
                    if (st%failed()) return
                    do k = 1, total
                        call read_part(k)
                        if (st%failed()) return
                    end do
                end do
            end do
            if (pass == 1) then
                if (zero) then
                    do c = 1, mesh%n_cells
                        if (n_points(c) > 0) cycle
                        if (location == FIELD_CART) then
                            np = 1
                        else if (associated(model)) then
                            np = element_point_count(model%element(c), mesh%cell_type(c), &
                                location)
                        else
                            np = 0
                        end if
                        if (np == 0) cycle
                        n_points(c) = np
                        n_sub(c) = 1
                        cell_set(c) = 1
                    end do
                end if
                sets(1)%cmp = [(j, j = 1, n_cmp)]
                call field_define_cells(f, n_points, n_sub, cell_set, sets, st)
                if (st%failed()) return
            end if
        end do
    contains
        ! Part k of the current type and entity: pass 1 its cells' layout, pass 2 its values.
        subroutine read_part(k)
            integer(i4), intent(in) :: k
            character(len=:), allocatable :: profile, localization
            integer(i4) :: n_pts, n_ent, nn, per_cell
            real(dp), allocatable :: values(:)
            call med_field_part_info(file, name, numdt, numit, entity, MED_CODES(t), k, &
                profile, localization, n_pts, n_ent, st)
            if (st%failed()) return
            call entities_of(file, profile, n_ent, counts(t), cells, st)
            if (st%failed()) return
            nn = CELL_TYPE_NODES(CELL_TYPE_ORDER(t))
            per_cell = max(n_pts, 1_i4)
            if (entity == MED_ENTITY_NODE_ELEMENT) per_cell = nn
            do e = 1, n_ent
                c = rank_cell(t, cells(e))
                select case (location)
                case (FIELD_ELGA)
                    np = 0
                    if (associated(model)) np = element_point_count(model%element(c), &
                        mesh%cell_type(c), FIELD_ELGA)
                case (FIELD_ELNO)
                    np = nn
                case default
                    np = 1
                end select
                if (np == 0 .or. mod(per_cell, max(np, 1_i4)) /= 0) then
                    call set_error(st, STATUS_MODEL_ERROR, 'the file gives cell number ' // &
                        to_text(c) // ' ' // to_text(per_cell) // ' point(s): no element ' // &
                        'family of MODELE on it has a divisor of that many (' // &
                        location_text(location) // ')')
                    return
                end if
                ns = per_cell / np
                if (pass == 1) then
                    n_points(c) = np
                    n_sub(c) = ns
                    cell_set(c) = 1
                end if
            end do
            if (pass == 1) return
            allocate (values(int(n_ent, i8) * per_cell * n_file))
            call med_read_entity_values(file, name, numdt, numit, entity, MED_CODES(t), &
                profile, values, st)
            if (st%failed()) return
            do e = 1, n_ent
                c = rank_cell(t, cells(e))
                do p = 1, per_cell
                    base = f%offset(c) + int(p - 1, i8) * n_cmp
                    do j = 1, n_cmp
                        f%values(base + j) = values((int(e - 1, i8) * per_cell + (p - 1)) * &
                            n_file + map(j))
                    end do
                end do
            end do
        end subroutine read_part
    end subroutine read_cells

    ! The entity numbers (1-based within the type) of a part: its profile's, or 1..n.
    subroutine entities_of(file, profile, n, capacity, numbers, st)
        type(med_file_t), intent(in) :: file
        character(len=*), intent(in) :: profile
        integer(i4), intent(in) :: n, capacity
        integer(i4), allocatable, intent(out) :: numbers(:)
        type(status_t), intent(out) :: st
        integer(i4) :: k
        if (len(profile) == 0) then
            numbers = [(k, k = 1, n)]
        else
            call med_read_profile(file, profile, capacity, numbers, st)
            if (st%failed()) return
        end if
        if (size(numbers) /= n .or. any(numbers < 1) .or. any(numbers > capacity)) then
            call set_error(st, STATUS_IO_ERROR, 'a part of the field gives ' // to_text(n) // &
                ' entities, its numbers do not fit the mesh (' // to_text(capacity) // ')')
        end if
    end subroutine entities_of

    pure function location_text(location) result(text)
        integer(i4), intent(in) :: location
        character(len=4) :: text
        select case (location)
        case (FIELD_ELGA)
            text = 'ELGA'
        case (FIELD_ELNO)
            text = 'ELNO'
        case (FIELD_ELEM)
            text = 'ELEM'
        case default
            text = 'CART'
        end select
    end function location_text

    ! Locates a failed status at `key`.

end module lire_champ_command
