!> CREA_TABLE (U4.33.02): a table from lists (LISTE), from a function (FONCTION) or from a
!> result's nodal field (RESU), as Code_Aster's op0036 builds it:
!>  - LISTE: one column per occurrence, named PARA, of the type of its list (LISTE_I: I,
!>    LISTE_R: R, LISTE_K: TYPE_K, default K8); value k goes to row k, or to row
!>    NUME_LIGN(k); the table has as many rows as its longest column; cells not given are
!>    absent. Column names must differ; NUME_LIGN has one row per value, no row twice.
!>  - FONCTION: two columns, the abscissae and the ordinates, named PARA or by the
!>    function's NOM_PARA and NOM_RESU.
!>  - RESU: a field of a result (RESULTAT, NOM_CHAM, TOUT_ORDRE / NUME_ORDRE / INST /
!>    LIST_INST) or a field concept (CHAM_GD), read through result_access (the field
!>    model): columns RESULTAT (INTITULE, default the result's name) and NOM_CHAM (or
!>    CHAM_GD), INST (when asked by INST or LIST_INST), NUME_ORDRE, MAILLE (element
!>    fields), NOEUD (NOEU, ELNO) or POINT (ELGA), SOUS_POINT (ELGA, ELNO, ELEM), COOR_X,
!>    COOR_Y, COOR_Z (the node; an ELGA point's position, Code_Aster's COOR_ELGA, a
!>    plate layer's sub-points along the normal; absent for ELEM and CART as in Code_Aster),
!>    then the components (TOUT_CMP: those the field holds, in its quantity's order;
!>    NOM_CMP: those named); CARA_ELEM gives the plates' layers of a CHAM_GD (default: those
!>    of the result it was extracted from);
!>    a row per instant and node (TOUT, GROUP_NO, GROUP_MA: their nodes, in the mesh's
!>    order) or per instant, cell, point and sub-point (TOUT, GROUP_MA).
!> TITRE gives the title. TYPE_TABLE other than TABLE (tables of functions or of concepts)
!> is not built by parasol: a located error says so.
module crea_table_command
    use kinds, only: dp, i4, i8
    use strings, only: string_t, to_text
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t
    use mesh_concept, only: mesh_concept_t
    use model_concept, only: model_concept_t
    use field_types, only: field_t, FIELD_NOEU, FIELD_ELGA, FIELD_ELNO, FIELD_ELEM, &
        field_is_cell_field, field_location_name, field_component, field_position
    use field_concept, only: field_concept_t
    use result_fields, only: result_fields_t
    use result_access, only: result_field_at, result_mesh
    use table_concept, only: table_t, table_init, table_add_column, table_add_rows, &
        table_set_int, table_set_real, table_set_text, table_append_title, TABLE_INT, &
        TABLE_REAL, TABLE_TEXT, MAX_TABLE_ROWS, table_entity_label
    use table_keywords, only: relocate_at
    use function_points, only: function_samples_t, samples_of_function
    use result_instants, only: selected_instants
    use crea_champ_command, only: selected_nodes, selected_cells
    use analysis_result, only: result_concept_t
    use model_types, only: model_t, is_plate
    use model_cara_elem, only: cara_elem_t
    use cara_elem_concept, only: cara_elem_concept_t
    use element_gauss_families, only: gauss_rule_t, gauss_point_positions, MAX_GAUSS_POINTS
    use element_plate, only: plate_local_frame
    use field_layout, only: element_points
    implicit none
    private

    !> The columns of a RESU table (0: absent) and the components it holds.
    type :: layout_t
        integer :: location = 0
        logical :: from_result = .true., by_inst = .false.
        integer :: c_label = 0, c_field = 0, c_inst = 0, c_order = 0, c_cell = 0, &
            c_node = 0, c_point = 0, c_subpoint = 0
        integer :: c_xyz(3) = 0
        integer, allocatable :: components(:), c_values(:)
    end type layout_t

    public :: run_crea_table, result_of_occurrence, nodes_of_occurrence, &
        cells_of_occurrence, mesh_of_support

contains

    !> Handler of CREA_TABLE.
    subroutine run_crea_table(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(table_t), allocatable :: t
        type(string_t), allocatable :: titles(:)
        character(len=:), allocatable :: kind
        integer :: k
        call cmd%get_text('TYPE_TABLE', kind, st)
        if (st%failed()) return
        if (kind /= 'TABLE') then
            call cmd%error_at('TYPE_TABLE', 'TYPE_TABLE=''' // kind // ''' (a table of ' // &
                'functions or of concepts) is not built by parasol: TYPE_TABLE=''TABLE'' is', &
                st, STATUS_NOT_IMPLEMENTED)
            return
        end if
        allocate (t)
        call table_init(t)
        if (cmd%count('LISTE') > 0) then
            call table_from_lists(cmd, t, st)
        else if (cmd%count('FONCTION') > 0) then
            call table_from_function(cmd%occurrence('FONCTION', 1), t, st)
        else if (cmd%count('RESU') > 0) then
            call table_from_result(cmd%occurrence('RESU', 1), t, st)
        end if
        if (st%failed()) return
        if (cmd%has('TITRE')) then
            call cmd%get_texts('TITRE', titles, st)
            if (st%failed()) return
            do k = 1, size(titles)
                call table_append_title(t, titles(k)%s)
            end do
        end if
        call move_alloc(t, result)
        if (ctx%checking) return
    end subroutine run_crea_table

    !> LISTE: a column per occurrence.
    subroutine table_from_lists(cmd, t, st)
        type(command_t), intent(in) :: cmd
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        type(keyword_set_t) :: occ
        integer :: k
        do k = 1, cmd%count('LISTE')
            occ = cmd%occurrence('LISTE', k)
            call add_list_column(occ, t, st)
            if (st%failed()) return
        end do
    end subroutine table_from_lists

    subroutine add_list_column(occ, t, st)
        type(keyword_set_t), intent(in) :: occ
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: para, type_k, key
        integer(i4), allocatable :: ints(:), rows(:)
        real(dp), allocatable :: reals(:)
        type(string_t), allocatable :: texts(:)
        integer :: column, n, k, width, kind
        logical, allocatable :: seen(:)
        call occ%get_text('PARA', para, st)
        if (st%ok()) call occ%get_text('TYPE_K', type_k, st)
        if (st%failed()) return
        if (occ%has('LISTE_I')) then
            key = 'LISTE_I'
            kind = TABLE_INT
            call occ%get_ints(key, ints, st)
            n = size(ints)
        else if (occ%has('LISTE_R')) then
            key = 'LISTE_R'
            kind = TABLE_REAL
            call occ%get_reals(key, reals, st)
            n = size(reals)
        else
            key = 'LISTE_K'
            kind = TABLE_TEXT
            call occ%get_texts(key, texts, st)
            n = size(texts)
        end if
        if (st%failed()) return
        if (occ%has('NUME_LIGN')) then
            call occ%get_ints('NUME_LIGN', rows, st)
            if (st%failed()) return
            if (size(rows) /= n) then
                call occ%error_at('NUME_LIGN', 'NUME_LIGN has ' // &
                    to_text(int(size(rows), i4)) // ' row number(s) but ' // key // ' has ' // &
                    to_text(int(n, i4)) // ' values (one row per value)', st)
                return
            end if
            if (any(rows > MAX_TABLE_ROWS)) then
                call occ%error_at('NUME_LIGN', 'a table has at most ' // &
                    to_text(int(MAX_TABLE_ROWS, i4)) // ' rows; NUME_LIGN asks for row ' // &
                    to_text(maxval(rows)), st)
                return
            end if
            allocate (seen(maxval([rows, 0])), source=.false.)
            do k = 1, n
                if (seen(rows(k))) then
                    call occ%error_at('NUME_LIGN', 'row ' // to_text(rows(k)) // &
                        ' is given twice', st)
                    return
                end if
                seen(rows(k)) = .true.
            end do
        else
            rows = [(int(k, i4), k=1, n)]
        end if
        width = 8
        if (type_k == 'K16') width = 16
        if (type_k == 'K24') width = 24
        call table_add_column(t, para, kind, column, st, width)
        if (st%failed()) then
            call relocate_at(occ, 'PARA', st)
            return
        end if
        if (n > 0) then
            if (maxval(rows) > t%n_rows) call table_add_rows(t, maxval(rows) - t%n_rows)
        end if
        do k = 1, n
            select case (kind)
            case (TABLE_INT)
                call table_set_int(t, column, rows(k), int(ints(k), i8), st)
            case (TABLE_REAL)
                call table_set_real(t, column, rows(k), reals(k), st)
            case default
                call table_set_text(t, column, rows(k), texts(k)%s, st)
            end select
            if (st%failed()) then
                call relocate_at(occ, key, st)
                return
            end if
        end do
    end subroutine add_list_column

    !> FONCTION: abscissae and ordinates.
    subroutine table_from_function(occ, t, st)
        type(keyword_set_t), intent(in) :: occ
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        class(concept_t), pointer :: f
        type(function_samples_t) :: samples
        type(string_t), allocatable :: names(:)
        integer :: cx, cy, k
        call occ%get_concept('FONCTION', f, st)
        if (st%failed()) return
        call samples_of_function(f, samples, st)
        if (st%failed()) then
            call relocate_at(occ, 'FONCTION', st)
            return
        end if
        allocate (names(2))
        names(1)%s = samples%parameter
        names(2)%s = samples%result_name
        if (occ%has('PARA')) call occ%get_texts('PARA', names, st)
        if (st%failed()) return
        if (names(1)%s == names(2)%s) then
            call occ%error_at('PARA', 'the two columns need different names (got ' // &
                names(1)%s // ' twice)', st)
            return
        end if
        call table_add_column(t, names(1)%s, TABLE_REAL, cx, st)
        if (st%ok()) call table_add_column(t, names(2)%s, TABLE_REAL, cy, st)
        if (st%failed()) return
        call table_add_rows(t, size(samples%x))
        do k = 1, size(samples%x)
            call table_set_real(t, cx, k, samples%x(k), st)
            call table_set_real(t, cy, k, samples%y(k), st)
        end do
    end subroutine table_from_function

    !> RESU: a field of a result (RESULTAT, NOM_CHAM, instants) or a field concept
    !> (CHAM_GD), a row per instant and node (NOEU) or per instant, cell, point and
    !> sub-point (ELGA, ELNO, ELEM, CART), as Code_Aster's ctresu.
    subroutine table_from_result(occ, t, st)
        type(keyword_set_t), intent(in) :: occ
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        class(result_fields_t), pointer :: res
        class(concept_t), pointer :: ptr
        type(field_t), pointer :: f
        type(mesh_t), pointer :: mesh
        type(model_t), pointer :: model
        type(cara_elem_t), pointer :: cara
        character(len=:), allocatable :: field, label
        integer, allocatable :: indices(:)
        integer :: i
        logical :: by_inst
        type(layout_t) :: layout
        res => null()
        f => null()
        model => null()
        cara => null()
        field = ''
        if (occ%has('RESULTAT')) then
            call result_of_occurrence(occ, res, st)
            if (st%ok() .and. .not. occ%has('NOM_CHAM')) call occ%error_at('RESULTAT', &
                'give NOM_CHAM, the field of the result to put in the table', st)
            if (st%ok()) call occ%get_text('NOM_CHAM', field, st)
            if (st%failed()) return
            call result_mesh(res, mesh, st)
            if (st%failed()) then
                call relocate_at(occ, 'RESULTAT', st)
                return
            end if
            label = res%name
            if (occ%has('INTITULE')) call occ%get_text('INTITULE', label, st)
            if (st%ok()) call selected_instants(occ, res, indices, by_inst, st)
            if (st%failed()) return
        else
            if (.not. occ%has('CHAM_GD')) then
                call occ%error_at('RESULTAT', 'give RESULTAT or CHAM_GD', st)
                return
            end if
            call occ%get_concept('CHAM_GD', ptr, st)
            if (st%failed()) return
            select type (ptr)
            type is (field_concept_t)
                f => ptr%field
                call mesh_of_support(ptr, mesh, st)
                if (st%ok()) call structure_of_support(ptr, model, cara)
            class default
                call occ%error_at('CHAM_GD', 'expected a field (cham_no, cham_elem or ' // &
                    'carte), got ' // ptr%type_name(), st)
            end select
            if (st%failed()) then
                call relocate_at(occ, 'CHAM_GD', st)
                return
            end if
            label = ptr%name
            if (occ%has('INTITULE')) call occ%get_text('INTITULE', label, st)
            if (st%failed()) return
            indices = [0]
            by_inst = .false.
        end if
        if (associated(res)) call structure_of_result(res, model, cara)
        if (occ%has('CARA_ELEM')) then
            call occ%get_concept('CARA_ELEM', ptr, st)
            if (st%failed()) return
            select type (ptr)
            type is (cara_elem_concept_t)
                cara => ptr%cara
            end select
        end if
        do i = 1, size(indices)
            if (associated(res)) then
                call result_field_at(res, int(indices(i), i4), field, f, st)
                if (st%failed()) then
                    call relocate_at(occ, 'NOM_CHAM', st)
                    return
                end if
            end if
            if (i == 1) then
                call table_layout(occ, f, associated(res), by_inst, layout, st)
                if (st%ok()) call add_layout_columns(t, layout, st)
                if (st%failed()) return
            end if
            if (associated(res)) then
                call append_field_rows(occ, t, layout, f, mesh, model, cara, label, field, &
                                       res%nume_ordre(indices(i)), res%inst(indices(i)), st)
            else
                call append_field_rows(occ, t, layout, f, mesh, model, cara, label, '', &
                                       0_i4, 0.0_dp, st)
            end if
            if (st%failed()) return
        end do
    end subroutine table_from_result

    !> The columns of a RESU table and the components (indices into f%components).
    subroutine table_layout(occ, f, from_result, by_inst, layout, st)
        type(keyword_set_t), intent(in) :: occ
        type(field_t), intent(in) :: f
        logical, intent(in) :: from_result, by_inst
        type(layout_t), intent(out) :: layout
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: names(:)
        integer :: k, c
        layout%location = f%location
        layout%from_result = from_result
        layout%by_inst = by_inst
        if (field_is_cell_field(f) .and. occ%has('GROUP_NO')) then
            call occ%error_at('GROUP_NO', 'the field is an element field (' // &
                field_location_name(f) // '): choose its cells with TOUT or GROUP_MA', st)
            return
        end if
        if (occ%has('NOM_VARI')) then
            call occ%error_at('NOM_VARI', 'internal variables by name are not read by ' // &
                'parasol: give their components V1, V2, ... in NOM_CMP', st, &
                STATUS_NOT_IMPLEMENTED)
            return
        end if
        if (occ%has('NOM_CMP')) then
            call occ%get_texts('NOM_CMP', names, st)
            if (st%failed()) return
            allocate (layout%components(0))
            do k = 1, size(names)
                c = field_component(f, names(k)%s)
                if (c == 0) then
                    call occ%error_at('NOM_CMP', 'the field has no component ' // &
                        names(k)%s // ' (it has ' // components_list(f) // ')', st, &
                        STATUS_MODEL_ERROR)
                    return
                end if
                if (.not. any(layout%components == c)) layout%components = &
                    [layout%components, c]
            end do
        else
            layout%components = present_components(f)
        end if
    end subroutine table_layout

    !> TOUT_CMP: the components the field holds (a cell field: those of some cell of it,
    !> as Code_Aster's CHAM_ELEM_S), in the quantity's order.
    function present_components(f) result(list)
        type(field_t), intent(in) :: f
        integer, allocatable :: list(:)
        logical, allocatable :: held(:)
        integer :: c, k
        if (.not. field_is_cell_field(f)) then
            list = [(k, k=1, size(f%components))]
            return
        end if
        allocate (held(size(f%components)), source=.false.)
        do c = 1, f%n_cells
            if (f%n_points(c) <= 0) cycle
            if (f%cell_set(c) < 1 .or. f%cell_set(c) > size(f%sets)) cycle
            held(f%sets(f%cell_set(c))%cmp) = .true.
        end do
        list = pack([(k, k=1, size(f%components))], held)
    end function present_components

    function components_list(f) result(text)
        type(field_t), intent(in) :: f
        character(len=:), allocatable :: text
        integer :: k
        text = ''
        do k = 1, size(f%components)
            if (k > 1) text = text // ' '
            text = text // f%components(k)%s
        end do
    end function components_list

    !> Code_Aster's columns (ctcrtb): RESULTAT, NOM_CHAM (or CHAM_GD), INST when asked by
    !> instants, NUME_ORDRE, MAILLE (cell fields), NOEUD (NOEU, ELNO) or POINT (ELGA),
    !> SOUS_POINT (ELGA, ELNO, ELEM), COOR_X, COOR_Y, COOR_Z, the components.
    subroutine add_layout_columns(t, layout, st)
        type(table_t), intent(inout) :: t
        type(layout_t), intent(inout) :: layout
        type(status_t), intent(inout) :: st
        integer :: k
        if (layout%from_result) then
            call table_add_column(t, 'RESULTAT', TABLE_TEXT, layout%c_label, st, 16)
            call table_add_column(t, 'NOM_CHAM', TABLE_TEXT, layout%c_field, st, 16)
            if (layout%by_inst) call table_add_column(t, 'INST', TABLE_REAL, layout%c_inst, st)
            call table_add_column(t, 'NUME_ORDRE', TABLE_INT, layout%c_order, st)
        else
            call table_add_column(t, 'CHAM_GD', TABLE_TEXT, layout%c_label, st, 16)
        end if
        if (layout%location /= FIELD_NOEU) call table_add_column(t, 'MAILLE', TABLE_TEXT, &
            layout%c_cell, st, 8)
        if (layout%location == FIELD_NOEU .or. layout%location == FIELD_ELNO) &
            call table_add_column(t, 'NOEUD', TABLE_TEXT, layout%c_node, st, 8)
        if (layout%location == FIELD_ELGA) call table_add_column(t, 'POINT', TABLE_INT, &
            layout%c_point, st)
        if (layout%location == FIELD_ELGA .or. layout%location == FIELD_ELNO .or. &
            layout%location == FIELD_ELEM) &
            call table_add_column(t, 'SOUS_POINT', TABLE_INT, layout%c_subpoint, st)
        ! always declared; ELEM and CART rows leave them absent (Code_Aster's cteltb)
        call table_add_column(t, 'COOR_X', TABLE_REAL, layout%c_xyz(1), st)
        call table_add_column(t, 'COOR_Y', TABLE_REAL, layout%c_xyz(2), st)
        call table_add_column(t, 'COOR_Z', TABLE_REAL, layout%c_xyz(3), st)
        if (st%failed()) return
        allocate (layout%c_values(size(layout%components)))
        layout%c_values = 0
        do k = 1, size(layout%components)
            ! named after the field's components by the first field (name_value_columns)
            if (st%ok()) call table_add_column(t, '?' // to_text(int(k, i4)), TABLE_REAL, &
                                               layout%c_values(k), st)
        end do
    end subroutine add_layout_columns

    !> The rows of one field (one instant).
    subroutine append_field_rows(occ, t, layout, f, mesh, model, cara, label, field, order, &
                                 inst, st)
        type(keyword_set_t), intent(in) :: occ
        type(table_t), intent(inout) :: t
        type(layout_t), intent(in) :: layout
        type(field_t), intent(in) :: f
        type(mesh_t), intent(in) :: mesh
        type(model_t), pointer, intent(in) :: model
        type(cara_elem_t), pointer, intent(in) :: cara
        character(len=*), intent(in) :: label, field
        integer(i4), intent(in) :: order
        real(dp), intent(in) :: inst
        type(status_t), intent(inout) :: st
        integer, allocatable :: nodes(:), cells(:)
        integer :: k, j, p, q, row, n_new, node, c
        integer(i8) :: pos
        real(dp), allocatable :: xyz(:, :, :)
        logical :: located
        call name_value_columns(t, layout, f)
        if (f%location == FIELD_NOEU) then
            call nodes_of_occurrence(occ, mesh, nodes, st)
            if (st%failed()) return
            nodes = pack(nodes, nodes <= f%n_nodes)
            call grow(size(nodes))
            if (st%failed()) return
            do k = 1, size(nodes)
                row = t%n_rows - size(nodes) + k
                call prefix(row)
                call table_set_text(t, layout%c_node, row, table_entity_label(nodes(k)), st)
                do j = 1, 3
                    call table_set_real(t, layout%c_xyz(j), row, mesh%coords(j, nodes(k)), st)
                end do
                do j = 1, size(layout%components)
                    if (f%node_has(layout%components(j), nodes(k))) call table_set_real(t, &
                        layout%c_values(j), row, f%node_values(layout%components(j), &
                        nodes(k)), st)
                end do
                if (st%failed()) return
            end do
            return
        end if
        call cells_of_occurrence(occ, mesh, cells, st)
        if (st%failed()) return
        cells = pack(cells, cells <= f%n_cells)
        cells = pack(cells, f%n_points(cells) > 0)
        n_new = 0
        do k = 1, size(cells)
            n_new = n_new + f%n_points(cells(k)) * f%n_subpoints(cells(k))
        end do
        call grow(n_new)
        if (st%failed()) return
        row = t%n_rows - n_new
        do k = 1, size(cells)
            c = cells(k)
            located = .false.
            if (f%location == FIELD_ELGA) call gauss_coordinates(mesh, model, cara, c, &
                f%n_points(c), f%n_subpoints(c), xyz, located)
            do p = 1, f%n_points(c)
                do q = 1, f%n_subpoints(c)
                    row = row + 1
                    call prefix(row)
                    call table_set_text(t, layout%c_cell, row, table_entity_label(c), st)
                    if (layout%c_point > 0) call table_set_int(t, layout%c_point, row, &
                        int(p, i8), st)
                    if (layout%c_subpoint > 0) call table_set_int(t, layout%c_subpoint, &
                        row, int(q, i8), st)
                    if (layout%c_node > 0) then
                        node = mesh%cell_nodes(mesh%cell_ptr(c) + p - 1)
                        call table_set_text(t, layout%c_node, row, table_entity_label(node), st)
                        do j = 1, 3
                            call table_set_real(t, layout%c_xyz(j), row, &
                                mesh%coords(j, node), st)
                        end do
                    else if (located) then
                        do j = 1, 3
                            call table_set_real(t, layout%c_xyz(j), row, xyz(j, q, p), st)
                        end do
                    end if
                    do j = 1, size(layout%components)
                        pos = field_position(f, c, p, q, layout%components(j))
                        if (pos > 0) call table_set_real(t, layout%c_values(j), row, &
                            f%values(pos), st)
                    end do
                end do
            end do
            if (st%failed()) return
        end do
    contains
        subroutine grow(n)
            integer, intent(in) :: n
            if (int(t%n_rows, i8) + n > MAX_TABLE_ROWS) then
                call occ%error_at('NOM_CHAM', 'the table would have more than ' // &
                    to_text(int(MAX_TABLE_ROWS, i4)) // ' rows', st, STATUS_MODEL_ERROR)
                return
            end if
            call table_add_rows(t, n)
        end subroutine grow

        subroutine prefix(r)
            integer, intent(in) :: r
            call table_set_text(t, layout%c_label, r, label, st)
            if (.not. layout%from_result) return
            call table_set_text(t, layout%c_field, r, field, st)
            if (layout%c_inst > 0) call table_set_real(t, layout%c_inst, r, inst, st)
            call table_set_int(t, layout%c_order, r, int(order, i8), st)
        end subroutine prefix
    end subroutine append_field_rows

    !> The coordinates of an ELGA field's points and sub-points on cell c, as Code_Aster's
    !> COOR_ELGA (te0488 for plates): the isoparametric image of the element family's
    !> reference points (field_layout element_points); on a plate with layers, sub-point
    !> (layer l, level 1..3) lies at z = -h/2 + (l-1) h/n + (level-1) h/(2n) along the
    !> cell's normal (element_plate's frame, Code_Aster's dxtpgl / dxqpgl). `located` is
    !> false when the model or the points are not known (the coordinates stay absent).
    subroutine gauss_coordinates(mesh, model, cara, c, np, nsub, xyz, located)
        type(mesh_t), intent(in) :: mesh
        type(model_t), pointer, intent(in) :: model
        type(cara_elem_t), pointer, intent(in) :: cara
        integer, intent(in) :: c
        integer(i4), intent(in) :: np, nsub
        real(dp), allocatable, intent(out) :: xyz(:, :, :)
        logical, intent(out) :: located
        type(gauss_rule_t) :: rule
        type(status_t) :: st
        real(dp) :: pos(3, MAX_GAUSS_POINTS), x(3, 9), rot(3, 3), xy(2, 9), h, z
        integer(i4) :: nn, kind, layers, p, q, lay, level
        located = .false.
        allocate (xyz(3, max(nsub, 1_i4), max(np, 1_i4)), source=0.0_dp)
        if (.not. associated(model)) return
        if (c > size(model%element)) return
        kind = model%element(c)
        nn = mesh%cell_ptr(c + 1) - mesh%cell_ptr(c)
        if (nn > size(x, 2) .or. np > MAX_GAUSS_POINTS) return
        call element_points(kind, mesh%cell_type(c), np, rule, st)
        if (st%failed()) return
        x(:, 1:nn) = mesh%coords(:, mesh%cell_nodes(mesh%cell_ptr(c):mesh%cell_ptr(c + 1) - 1))
        call gauss_point_positions(rule, x(:, 1:nn), pos(:, 1:np))
        do p = 1, np
            do q = 1, nsub
                xyz(:, q, p) = pos(:, p)
            end do
        end do
        located = .true.
        if (nsub <= 1 .or. .not. is_plate(kind) .or. .not. associated(cara)) return
        if (c > size(cara%thickness)) return
        layers = max(1_i4, cara%coque_layers(c))
        if (nsub /= 3 * layers) return
        call plate_local_frame(x(:, 1:nn), nn, rot, xy(:, 1:nn), st)
        if (st%failed()) return
        h = cara%thickness(c)
        do p = 1, np
            q = 0
            do lay = 1, layers
                do level = 1, 3
                    q = q + 1
                    z = -h / 2.0_dp + (lay - 1) * (h / layers) + (level - 1) * (h / layers) / 2.0_dp
                    xyz(:, q, p) = pos(:, p) + z * rot(3, :)
                end do
            end do
        end do
    end subroutine gauss_coordinates

    !> The model and characteristics a result was computed with (none for a result made
    !> by CREA_RESU).
    subroutine structure_of_result(res, model, cara)
        class(result_fields_t), target, intent(in) :: res
        type(model_t), pointer, intent(inout) :: model
        type(cara_elem_t), pointer, intent(inout) :: cara
        select type (res)
        type is (result_concept_t)
            if (allocated(res%model%element)) model => res%model
            if (allocated(res%cara%thickness)) cara => res%cara
        end select
    end subroutine structure_of_result

    !> The model (and characteristics) behind a field concept's support: a model, or the
    !> result it was extracted from.
    subroutine structure_of_support(fc, model, cara)
        type(field_concept_t), intent(in) :: fc
        type(model_t), pointer, intent(inout) :: model
        type(cara_elem_t), pointer, intent(inout) :: cara
        if (.not. associated(fc%support)) return
        select type (support => fc%support)
        type is (model_concept_t)
            model => support%model
        class is (result_fields_t)
            call structure_of_result(support, model, cara)
        end select
    end subroutine structure_of_support

    !> Names the component columns after the field (the first field decides).
    subroutine name_value_columns(t, layout, f)
        type(table_t), intent(inout) :: t
        type(layout_t), intent(in) :: layout
        type(field_t), intent(in) :: f
        integer :: j
        do j = 1, size(layout%components)
            if (t%columns(layout%c_values(j))%name(1:1) == '?') &
                t%columns(layout%c_values(j))%name = f%components(layout%components(j))%s
        end do
    end subroutine name_value_columns

    !> The cells an occurrence designates: TOUT (every cell), GROUP_MA (each cell once, in
    !> the mesh's order).
    subroutine cells_of_occurrence(occ, mesh, cells, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        integer, allocatable, intent(out) :: cells(:)
        type(status_t), intent(inout) :: st
        logical, allocatable :: chosen(:)
        integer :: k
        allocate (cells(0))
        if (.not. (occ%has('TOUT') .or. occ%has('GROUP_MA'))) return
        call selected_cells(occ, mesh, chosen, st)
        if (st%ok()) cells = pack([(k, k=1, mesh%n_cells)], chosen)
    end subroutine cells_of_occurrence

    !> The mesh a field concept's numbers refer to (its support: a maillage or a modele).
    subroutine mesh_of_support(fc, mesh, st)
        type(field_concept_t), intent(in) :: fc
        type(mesh_t), pointer, intent(out) :: mesh
        type(status_t), intent(inout) :: st
        mesh => null()
        if (.not. associated(fc%support)) then
            call set_error(st, STATUS_MODEL_ERROR, 'the field knows no mesh')
            return
        end if
        select type (support => fc%support)
        type is (mesh_concept_t)
            mesh => support%mesh
        type is (model_concept_t)
            mesh => support%mesh
        class is (result_fields_t)
            call result_mesh(support, mesh, st)
        class default
            call set_error(st, STATUS_MODEL_ERROR, 'the field''s support is a ' // &
                support%type_name() // ', not a mesh or a model')
        end select
    end subroutine mesh_of_support

    !> The result given at RESULTAT of an occurrence.
    !>  st : located at RESULTAT when it is not a result
    subroutine result_of_occurrence(occ, res, st)
        class(keyword_set_t), intent(in) :: occ
        class(result_fields_t), pointer, intent(out) :: res
        type(status_t), intent(inout) :: st
        class(concept_t), pointer :: ptr
        res => null()
        call occ%get_concept('RESULTAT', ptr, st)
        if (st%failed()) return
        select type (ptr)
        class is (result_fields_t)
            res => ptr
        class default
            call occ%error_at('RESULTAT', 'expected a result (evol_elas, evol_noli, ...), ' // &
                'got ' // ptr%type_name(), st)
        end select
    end subroutine result_of_occurrence

    !> The nodes an occurrence designates: TOUT (every node), GROUP_NO and GROUP_MA (the
    !> nodes of their cells), NOEUD; each node once, in the mesh's order.
    !>  st : located at the group or node that does not exist
    subroutine nodes_of_occurrence(occ, mesh, nodes, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        integer, allocatable, intent(out) :: nodes(:)
        type(status_t), intent(inout) :: st
        logical, allocatable :: chosen(:)
        integer :: k
        allocate (nodes(0))
        call selected_nodes(occ, mesh, chosen, st)
        if (st%ok()) nodes = pack([(k, k=1, mesh%n_nodes)], chosen)
    end subroutine nodes_of_occurrence

end module crea_table_command
