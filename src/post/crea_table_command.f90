!> CREA_TABLE (U4.33.02): a table from lists (LISTE), from a function (FONCTION) or from a
!> result's nodal field (RESU), as Code_Aster's op0036 builds it:
!>  - LISTE: one column per occurrence, named PARA, of the type of its list (LISTE_I: I,
!>    LISTE_R: R, LISTE_K: TYPE_K, default K8); value k goes to row k, or to row
!>    NUME_LIGN(k); the table has as many rows as its longest column; cells not given are
!>    absent. Column names must differ; NUME_LIGN has one row per value, no row twice.
!>  - FONCTION: two columns, the abscissae and the ordinates, named PARA or by the
!>    function's NOM_PARA and NOM_RESU.
!>  - RESU with RESULTAT and a nodal NOM_CHAM (DEPL, FORC_NODA, REAC_NODA): columns
!>    RESULTAT (INTITULE, default the result's name), NOM_CHAM, INST (when asked by INST or
!>    LIST_INST), NUME_ORDRE, NOEUD, COOR_X, COOR_Y, COOR_Z, then the components (TOUT_CMP:
!>    those of the field, in the order DX DY DZ DRX DRY DRZ; NOM_CMP: those named), one row
!>    per instant and node (TOUT: every node of the mesh; GROUP_NO / GROUP_MA: their nodes,
!>    in the mesh's order).
!> TITRE gives the title. TYPE_TABLE other than TABLE (tables of functions or of concepts)
!> is not built by parasol: a located error says so.
module crea_table_command
    use kinds, only: dp, i4, i8
    use strings, only: string_t, to_text
    use status, only: status_t, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, find_node_group, find_cell_group, nodes_of_group, &
        cells_of_group, node_name
    use model_dof_numbering, only: COMPONENT_NAMES, N_COMPONENTS, component_index
    use analysis_result, only: result_concept_t, is_cell_field
    use table_concept, only: table_t, table_init, table_add_column, table_add_rows, &
        table_set_int, table_set_real, table_set_text, table_append_title, TABLE_INT, &
        TABLE_REAL, TABLE_TEXT, MAX_TABLE_ROWS
    use table_keywords, only: relocate_at
    use function_points, only: function_samples_t, samples_of_function
    use result_instants, only: selected_instants
    implicit none
    private

    public :: run_crea_table, result_of_occurrence, nodes_of_occurrence

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
                    to_text(int(size(rows), i4)) // ' row numbers but ' // key // ' has ' // &
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

    !> RESU: a result's nodal field at its nodes and instants.
    subroutine table_from_result(occ, t, st)
        type(keyword_set_t), intent(in) :: occ
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        type(result_concept_t), pointer :: res
        character(len=:), allocatable :: field, label
        type(string_t), allocatable :: names(:)
        integer, allocatable :: indices(:), comps(:), nodes(:)
        integer :: c_resu, c_cham, c_inst, c_ordre, c_noeud, c_x, c_y, c_z, k, i, n, row, eq
        integer, allocatable :: c_comp(:)
        logical :: by_inst
        if (.not. occ%has('RESULTAT')) then
            call occ%error_at('RESULTAT', 'CREA_TABLE/RESU reads a result: give RESULTAT ' // &
                '(CHAM_GD, a field concept, is not built by parasol yet)', st, &
                STATUS_NOT_IMPLEMENTED)
            return
        end if
        call result_of_occurrence(occ, res, st)
        if (st%failed()) return
        if (.not. occ%has('NOM_CHAM')) then
            call occ%error_at('RESULTAT', 'give NOM_CHAM, the field to put in the table', st)
            return
        end if
        call occ%get_text('NOM_CHAM', field, st)
        if (st%failed()) return
        if (is_cell_field(field) .or. .not. any(field == ['DEPL     ', 'FORC_NODA', &
                                                          'REAC_NODA'])) then
            call occ%error_at('NOM_CHAM', 'CREA_TABLE/RESU reads the nodal fields parasol''s ' &
                // 'results hold (DEPL, FORC_NODA, REAC_NODA), not ' // field, st, &
                STATUS_NOT_IMPLEMENTED)
            return
        end if
        label = res%name
        if (occ%has('INTITULE')) call occ%get_text('INTITULE', label, st)
        if (st%failed()) return
        call selected_instants(occ, res, indices, by_inst, st)
        if (st%failed()) return
        call nodes_of_occurrence(occ, res%mesh, nodes, st)
        if (st%failed()) return
        ! the components: those of the field (TOUT_CMP) or NOM_CMP
        if (occ%has('NOM_CMP')) then
            call occ%get_texts('NOM_CMP', names, st)
            if (st%failed()) return
            allocate (comps(size(names)))
            do k = 1, size(names)
                comps(k) = component_index(names(k)%s)
                if (comps(k) == 0 .or. .not. any(res%dofs%equation(max(comps(k), 1), :) > 0)) &
                    then
                    call occ%error_at('NOM_CMP', field // ' of ' // res%name // ' has no ' // &
                        'component ' // names(k)%s // ' (it has ' // &
                        field_components(res) // ')', st, STATUS_MODEL_ERROR)
                    return
                end if
            end do
        else
            comps = pack([(k, k=1, N_COMPONENTS)], &
                         [(any(res%dofs%equation(k, :) > 0), k=1, N_COMPONENTS)])
        end if
        call table_add_column(t, 'RESULTAT', TABLE_TEXT, c_resu, st, 16)
        call table_add_column(t, 'NOM_CHAM', TABLE_TEXT, c_cham, st, 16)
        c_inst = 0
        if (by_inst) call table_add_column(t, 'INST', TABLE_REAL, c_inst, st)
        call table_add_column(t, 'NUME_ORDRE', TABLE_INT, c_ordre, st)
        call table_add_column(t, 'NOEUD', TABLE_TEXT, c_noeud, st, 8)
        call table_add_column(t, 'COOR_X', TABLE_REAL, c_x, st)
        call table_add_column(t, 'COOR_Y', TABLE_REAL, c_y, st)
        call table_add_column(t, 'COOR_Z', TABLE_REAL, c_z, st)
        allocate (c_comp(size(comps)))
        do k = 1, size(comps)
            if (st%ok()) call table_add_column(t, trim(COMPONENT_NAMES(comps(k))), TABLE_REAL, &
                                               c_comp(k), st)
        end do
        if (st%failed()) return
        n = size(indices) * size(nodes)
        if (n > MAX_TABLE_ROWS) then
            call occ%error_at('RESULTAT', 'the table would have ' // to_text(int(n, i4)) // &
                ' rows, more than ' // to_text(int(MAX_TABLE_ROWS, i4)), st, STATUS_MODEL_ERROR)
            return
        end if
        call table_add_rows(t, n)
        row = 0
        do i = 1, size(indices)
            do k = 1, size(nodes)
                row = row + 1
                call table_set_text(t, c_resu, row, label, st)
                call table_set_text(t, c_cham, row, field, st)
                if (c_inst > 0) call table_set_real(t, c_inst, row, res%inst(indices(i)), st)
                call table_set_int(t, c_ordre, row, int(res%nume_ordre(indices(i)), i8), st)
                call table_set_text(t, c_noeud, row, node_name(res%mesh, nodes(k)), st)
                call table_set_real(t, c_x, row, res%mesh%coords(1, nodes(k)), st)
                call table_set_real(t, c_y, row, res%mesh%coords(2, nodes(k)), st)
                call table_set_real(t, c_z, row, res%mesh%coords(3, nodes(k)), st)
                do n = 1, size(comps)
                    eq = res%dofs%equation(comps(n), nodes(k))
                    if (eq == 0) cycle
                    select case (field)
                    case ('DEPL')
                        call table_set_real(t, c_comp(n), row, res%depl(eq, indices(i)), st)
                    case ('FORC_NODA')
                        call table_set_real(t, c_comp(n), row, res%forc_noda(eq, indices(i)), st)
                    case default
                        call table_set_real(t, c_comp(n), row, res%reac_noda(eq, indices(i)), st)
                    end select
                end do
                if (st%failed()) then
                    call relocate_at(occ, 'RESULTAT', st)
                    return
                end if
            end do
        end do
    end subroutine table_from_result

    !> The components the result's nodal fields have, in words.
    function field_components(res) result(text)
        type(result_concept_t), intent(in) :: res
        character(len=:), allocatable :: text
        integer :: k
        text = ''
        do k = 1, N_COMPONENTS
            if (.not. any(res%dofs%equation(k, :) > 0)) cycle
            if (len(text) > 0) text = text // ' '
            text = text // trim(COMPONENT_NAMES(k))
        end do
        if (len(text) == 0) text = 'none'
    end function field_components

    !> The result given at RESULTAT of an occurrence.
    !>  st : located at RESULTAT when it is not a result
    subroutine result_of_occurrence(occ, res, st)
        class(keyword_set_t), intent(in) :: occ
        type(result_concept_t), pointer, intent(out) :: res
        type(status_t), intent(inout) :: st
        class(concept_t), pointer :: ptr
        res => null()
        call occ%get_concept('RESULTAT', ptr, st)
        if (st%failed()) return
        select type (ptr)
        type is (result_concept_t)
            res => ptr
        class default
            call occ%error_at('RESULTAT', 'expected a result (evol_elas or evol_noli), ' // &
                'got ' // ptr%type_name(), st)
        end select
    end subroutine result_of_occurrence

    !> The nodes an occurrence designates: TOUT (every node), GROUP_NO and GROUP_MA (the
    !> nodes of their cells), NOEUD; each node once, in the mesh's order.
    !>  st : located at the group or node that does not exist
    subroutine nodes_of_occurrence(occ, mesh, nodes, st)
        class(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        integer, allocatable, intent(out) :: nodes(:)
        type(status_t), intent(inout) :: st
        logical, allocatable :: chosen(:)
        type(string_t), allocatable :: names(:)
        integer(i4), allocatable :: members(:)
        integer(i4) :: g, c
        integer :: k, i
        allocate (chosen(mesh%n_nodes), source=.false.)
        if (occ%has('TOUT')) chosen = .true.
        if (occ%has('GROUP_NO')) then
            call occ%get_texts('GROUP_NO', names, st)
            if (st%failed()) return
            do k = 1, size(names)
                g = find_node_group(mesh, names(k)%s, st)
                if (st%failed()) then
                    call relocate_at(occ, 'GROUP_NO', st)
                    return
                end if
                members = nodes_of_group(mesh, g)
                chosen(members) = .true.
            end do
        end if
        if (occ%has('GROUP_MA')) then
            call occ%get_texts('GROUP_MA', names, st)
            if (st%failed()) return
            do k = 1, size(names)
                g = find_cell_group(mesh, names(k)%s, st)
                if (st%failed()) then
                    call relocate_at(occ, 'GROUP_MA', st)
                    return
                end if
                members = cells_of_group(mesh, g)
                do i = 1, size(members)
                    c = members(i)
                    chosen(mesh%cell_nodes(mesh%cell_ptr(c):mesh%cell_ptr(c + 1) - 1)) = .true.
                end do
            end do
        end if
        nodes = pack([(k, k=1, mesh%n_nodes)], chosen)
    end subroutine nodes_of_occurrence

end module crea_table_command
