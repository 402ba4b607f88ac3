!> POST_ELEM MINMAX (U4.81.22): the extrema in space of components of a field, per stored
!> instant, as Code_Aster's pemima / pemaxn / pemaxe tabulate them. Columns CHAMP_GD (the
!> NOM_CHAM read, or the CHAM_GD's name), NUME_ORDRE, INST (0 and 0 for a CHAM_GD), then,
!> added when first needed, a column named after the place (TOUT or GROUP_MA) holding its
!> name (TOUT, the group, UNION_GROUP_MA for the union of several groups), and per
!> component
!>  - nodal field: MAX_c, NO_MAX_c (the node), MIN_c, NO_MIN_c;
!>  - element field (one sub-point): MAX_c, MA_MAX_c (the cell), PT_MAX_c (its point),
!>    MIN_c, MA_MIN_c, PT_MIN_c;
!> the first node / cell / point in the mesh's order wins a tie, as Code_Aster's strict
!> comparisons make it. GROUP_MA: the nodes of its cells (nodal) or its cells. Rows by
!> occurrence, then instant, then TOUT, each group, their union. Not built, each a located
!> error: fields with sub-points (plate layers: extract one with POST_CHAMP EXTR_COQUE),
!> internal variables (VARI), a component the field lacks.
module post_elem_minmax
    use kinds, only: dp, i4, i8
    use strings, only: string_t
    use status, only: status_t, STATUS_NOT_IMPLEMENTED
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use mesh_types, only: mesh_t, find_cell_group, cells_of_group, nodes_of_cells
    use field_types, only: field_t, FIELD_NOEU, field_component, field_position, &
        field_is_cell_field
    use field_concept, only: field_concept_t
    use result_fields, only: result_fields_t
    use result_access, only: result_field_at, result_mesh
    use result_instants, only: selected_instants
    use table_concept, only: table_t, table_add_column, table_add_rows, table_set_int, &
        table_set_real, table_set_text, table_find_column, TABLE_INT, TABLE_REAL, TABLE_TEXT, &
        table_entity_label
    use table_keywords, only: relocate_at
    use crea_table_command, only: result_of_occurrence, mesh_of_support
    implicit none
    private
    public :: minmax_rows

contains

    !> MINMAX: the table's columns and rows (module header).
    subroutine minmax_rows(cmd, t, st)
        type(command_t), intent(in) :: cmd
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        type(keyword_set_t) :: occ
        integer :: k, c
        call table_add_column(t, 'CHAMP_GD', TABLE_TEXT, c, st, 16)
        call table_add_column(t, 'NUME_ORDRE', TABLE_INT, c, st)
        call table_add_column(t, 'INST', TABLE_REAL, c, st)
        do k = 1, cmd%count('MINMAX')
            if (st%failed()) return
            occ = cmd%occurrence('MINMAX', k)
            call occurrence_rows(occ, t, st)
        end do
    end subroutine minmax_rows

    subroutine occurrence_rows(occ, t, st)
        type(keyword_set_t), intent(in) :: occ
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        class(result_fields_t), pointer :: res
        class(concept_t), pointer :: p
        type(field_concept_t), pointer :: cham
        type(mesh_t), pointer :: mesh
        type(field_t), pointer :: f
        type(string_t), allocatable :: cmps(:), groups(:)
        character(len=:), allocatable :: label
        integer, allocatable :: indices(:)
        logical, allocatable :: union(:), cells(:)
        logical :: by_inst
        integer :: j, g, kc
        integer(i4) :: group
        res => null()
        cham => null()
        if (occ%has('RESULTAT')) then
            if (.not. occ%has('NOM_CHAM')) then
                call occ%error_at('RESULTAT', 'give NOM_CHAM, the field of the result', st)
                return
            end if
            call result_of_occurrence(occ, res, st)
            if (st%ok()) call occ%get_text('NOM_CHAM', label, st)
            if (st%ok()) call selected_instants(occ, res, indices, by_inst, st)
            if (st%ok()) call result_mesh(res, mesh, st)
            if (st%failed()) then
                call relocate_at(occ, 'RESULTAT', st)
                return
            end if
        else
            call occ%get_concept('CHAM_GD', p, st)
            if (st%failed()) return
            select type (p)
            type is (field_concept_t)
                cham => p
                label = p%name
                call mesh_of_support(p, mesh, st)
                if (st%failed()) call relocate_at(occ, 'CHAM_GD', st)
            class default
                call occ%error_at('CHAM_GD', 'expected a field (cham_no or cham_elem), ' // &
                    'got ' // p%type_name(), st)
            end select
            if (st%failed()) return
            indices = [0]
        end if
        call occ%get_texts('NOM_CMP', cmps, st)
        if (st%failed()) return
        allocate (groups(0))
        if (occ%has('GROUP_MA')) call occ%get_texts('GROUP_MA', groups, st)
        if (st%failed()) return
        do j = 1, size(indices)
            if (associated(res)) then
                call result_field_at(res, int(indices(j), i4), label, f, st)
                if (st%failed()) then
                    call relocate_at(occ, 'NOM_CHAM', st)
                    return
                end if
            else
                f => cham%field
            end if
            call check_field(occ, f, cmps, st)
            if (st%failed()) return
            if (occ%has('TOUT')) then
                allocate (cells(mesh%n_cells), source=.true.)
                call add_row('TOUT', 'TOUT', cells)
                deallocate (cells)
            end if
            allocate (union(mesh%n_cells), source=.false.)
            do g = 1, size(groups)
                group = find_cell_group(mesh, groups(g)%s, st)
                if (st%failed()) then
                    call relocate_at(occ, 'GROUP_MA', st)
                    return
                end if
                allocate (cells(mesh%n_cells), source=.false.)
                cells(cells_of_group(mesh, group)) = .true.
                union = union .or. cells
                call add_row('GROUP_MA', groups(g)%s, cells)
                deallocate (cells)
            end do
            if (size(groups) > 1) call add_row('GROUP_MA', 'UNION_GROUP_MA', union)
            deallocate (union)
            if (st%failed()) return
        end do
    contains
        !> One row: the extrema of every component over the chosen cells (or their nodes).
        subroutine add_row(place, where, chosen)
            character(len=*), intent(in) :: place, where
            logical, intent(in) :: chosen(:)
            integer :: r
            if (st%failed()) return
            call table_add_rows(t, 1)
            r = t%n_rows
            call table_set_text(t, 1, r, label, st)
            if (associated(res)) then
                call table_set_int(t, 2, r, int(res%nume_ordre(indices(j)), i8), st)
                call table_set_real(t, 3, r, res%inst(indices(j)), st)
            else
                call table_set_int(t, 2, r, 0_i8, st)
                call table_set_real(t, 3, r, 0.0_dp, st)
            end if
            call table_set_text(t, column(place, TABLE_TEXT, 24), r, where, st)
            do kc = 1, size(cmps)
                if (f%location == FIELD_NOEU) then
                    call nodal_extrema(cmps(kc)%s, chosen, r)
                else
                    call cell_extrema(cmps(kc)%s, chosen, r)
                end if
            end do
        end subroutine add_row

        subroutine nodal_extrema(name, chosen, r)
            character(len=*), intent(in) :: name
            logical, intent(in) :: chosen(:)
            integer, intent(in) :: r
            integer(i4), allocatable :: nodes(:)
            integer(i4) :: k, n, nmax, nmin, i
            real(dp) :: vmax, vmin
            k = field_component(f, name)
            nodes = nodes_of_cells(mesh, pack([(i, i=1_i4, mesh%n_cells)], chosen))
            if (all(chosen)) nodes = [(i, i=1_i4, mesh%n_nodes)]
            nmax = 0
            nmin = 0
            vmax = -huge(1.0_dp)
            vmin = huge(1.0_dp)
            do i = 1, size(nodes)
                n = nodes(i)
                if (.not. f%node_has(k, n)) cycle
                if (f%node_values(k, n) > vmax) then
                    vmax = f%node_values(k, n)
                    nmax = n
                end if
                if (f%node_values(k, n) < vmin) then
                    vmin = f%node_values(k, n)
                    nmin = n
                end if
            end do
            if (nmax == 0) return
            call table_set_real(t, column('MAX_' // name, TABLE_REAL, 0), r, vmax, st)
            call table_set_text(t, column('NO_MAX_' // name, TABLE_TEXT, 16), r, &
                table_entity_label(nmax), st)
            call table_set_real(t, column('MIN_' // name, TABLE_REAL, 0), r, vmin, st)
            call table_set_text(t, column('NO_MIN_' // name, TABLE_TEXT, 16), r, &
                table_entity_label(nmin), st)
        end subroutine nodal_extrema

        subroutine cell_extrema(name, chosen, r)
            character(len=*), intent(in) :: name
            logical, intent(in) :: chosen(:)
            integer, intent(in) :: r
            integer(i4) :: k, c, ip, cmax, cmin, pmax, pmin
            integer(i8) :: pos
            real(dp) :: vmax, vmin
            k = field_component(f, name)
            cmax = 0
            cmin = 0
            pmax = 0
            pmin = 0
            vmax = -huge(1.0_dp)
            vmin = huge(1.0_dp)
            do c = 1, min(mesh%n_cells, f%n_cells)
                if (.not. chosen(c)) cycle
                do ip = 1, f%n_points(c)
                    pos = field_position(f, c, ip, 1_i4, k)
                    if (pos == 0) cycle
                    if (f%values(pos) > vmax) then
                        vmax = f%values(pos)
                        cmax = c
                        pmax = ip
                    end if
                    if (f%values(pos) < vmin) then
                        vmin = f%values(pos)
                        cmin = c
                        pmin = ip
                    end if
                end do
            end do
            if (cmax == 0) return
            call table_set_real(t, column('MAX_' // name, TABLE_REAL, 0), r, vmax, st)
            call table_set_text(t, column('MA_MAX_' // name, TABLE_TEXT, 16), r, &
                table_entity_label(cmax), st)
            call table_set_int(t, column('PT_MAX_' // name, TABLE_INT, 0), r, &
                int(pmax, i8), st)
            call table_set_real(t, column('MIN_' // name, TABLE_REAL, 0), r, vmin, st)
            call table_set_text(t, column('MA_MIN_' // name, TABLE_TEXT, 16), r, &
                table_entity_label(cmin), st)
            call table_set_int(t, column('PT_MIN_' // name, TABLE_INT, 0), r, &
                int(pmin, i8), st)
        end subroutine cell_extrema

        !> The column `name`, added at the end when the table lacks it (tbajpa).
        integer function column(name, kind, width) result(c)
            character(len=*), intent(in) :: name
            integer, intent(in) :: kind, width
            c = table_find_column(t, name)
            if (c > 0) return
            if (kind == TABLE_TEXT) then
                call table_add_column(t, name, kind, c, st, width)
            else
                call table_add_column(t, name, kind, c, st)
            end if
        end function column
    end subroutine occurrence_rows

    !> The field must hold the components, without sub-points.
    subroutine check_field(occ, f, cmps, st)
        type(keyword_set_t), intent(in) :: occ
        type(field_t), intent(in) :: f
        type(string_t), intent(in) :: cmps(:)
        type(status_t), intent(inout) :: st
        integer :: k
        do k = 1, size(cmps)
            if (field_component(f, cmps(k)%s) == 0) then
                call occ%error_at('NOM_CMP', 'the field has no component ' // cmps(k)%s, st)
                return
            end if
        end do
        if (f%quantity == 'VARI_R') then
            call occ%error_at('NOM_CMP', 'MINMAX of internal variables (VARI) is not ' // &
                'built by parasol', st, STATUS_NOT_IMPLEMENTED)
        else if (field_is_cell_field(f)) then
            if (any(f%n_subpoints > 1 .and. f%n_points > 0)) call occ%error_at('NOM_CMP', &
                'the field has sub-points (plate layers): extract one with POST_CHAMP ' // &
                'EXTR_COQUE first (Code_Aster reads one sub-point)', st, &
                STATUS_NOT_IMPLEMENTED)
        end if
    end subroutine check_field

end module post_elem_minmax
