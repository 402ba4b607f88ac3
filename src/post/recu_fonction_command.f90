!> RECU_FONCTION (U4.32.03): a function (tabulated, LIN LIN) from
!>  - RESULTAT + NOM_CHAM + NOM_CMP: the component's value at a node (NOEUD, or the first
!>    node of GROUP_NO) of a nodal field, or at a cell (MAILLE, or the first cell of
!>    GROUP_MA) and POINT / SOUS_POINT (ELGA; ELNO also at NOEUD / GROUP_NO, the cell's
!>    node) of an element field, against INST, over TOUT_ORDRE (default) / NUME_ORDRE /
!>    INST / LIST_INST, taken in storage order, each once (Code_Aster's rfresu, rsutnu; a
!>    group of several nodes or cells takes its first one with a warning, as Code_Aster's
!>    alarm). The fields are read through
!>    result_access, so any field a result holds or provides can be followed.
!>  - RESULTAT + NOM_PARA_RESU: a parameter of the result against INST (parasol's results
!>    have INST only).
!>  - TABLE + PARA_X + PARA_Y (+ FILTRE, TEST_TABLE's rules): the rows holding both
!>    columns (Code_Aster's rftabl / tbexfo).
!> Abscissae are then ordered as Code_Aster's ordonn orders them: strictly decreasing ones
!> are reversed, unordered ones sorted (each with a warning), a repeated abscissa is an
!> error. Defaults: NOM_PARA INST (table: PARA_X), NOM_RESU the component (table: PARA_Y),
!> INTERPOL LIN LIN, PROL_GAUCHE / PROL_DROITE EXCLU; the keywords of those names override
!> them (INTERPOL LOG is not built: an error says so).
module recu_fonction_command
    use kinds, only: dp, i4
    use strings, only: string_t, to_text, real_e13
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use deck_concept, only: concept_t, concept_display_name
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, find_node, find_cell, find_node_group, find_cell_group, &
        nodes_of_group, cells_of_group, node_name, cell_name
    use field_types, only: field_t, FIELD_NOEU, FIELD_ELNO, field_node_value, &
        field_cell_value, field_is_cell_field
    use result_fields, only: result_fields_t
    use result_access, only: result_field_at, result_mesh
    use tabulated_function, only: tabulated_function_t, prolongation_code, PROL_EXCLU
    use table_concept, only: table_t, table_require_column, table_is_number, &
        table_kind_label, table_cell_real
    use table_keywords, only: table_of_keyword, filter_rows_of_command, relocate_at, warn_at
    use table_sort, only: real_order
    use result_instants, only: selected_instants
    use crea_table_command, only: result_of_occurrence
    implicit none
    private

    !> Where a function is read in a field.
    type :: place_t
        integer :: node = 0, cell = 0, point = 0, subpoint = 0
    end type place_t

    public :: run_recu_fonction, order_abscissae, set_function_attributes

contains

    !> Handler of RECU_FONCTION.
    subroutine run_recu_fonction(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(tabulated_function_t), allocatable :: f
        character(len=:), allocatable :: key
        allocate (f)
        f%left = PROL_EXCLU
        f%right = PROL_EXCLU
        if (cmd%has('TABLE')) then
            key = 'TABLE'
            call function_from_table(cmd, f, st)
        else if (cmd%has('RESULTAT')) then
            key = 'RESULTAT'
            call function_from_result(ctx, cmd, f, st)
        else
            call cmd%error_at('CHAM_GD', 'a function from a field concept (CHAM_GD) is not ' // &
                'built by parasol: give RESULTAT or TABLE', st, STATUS_NOT_IMPLEMENTED)
            return
        end if
        if (st%failed()) return
        call order_abscissae(ctx, cmd, key, f%x, f%y, st)
        if (st%ok()) call set_function_attributes(cmd, f, st)
        if (st%failed()) return
        call move_alloc(f, result)
    end subroutine run_recu_fonction

    !> TABLE, PARA_X, PARA_Y, FILTRE.
    subroutine function_from_table(cmd, f, st)
        type(command_t), intent(in) :: cmd
        type(tabulated_function_t), intent(inout) :: f
        type(status_t), intent(inout) :: st
        type(table_t), pointer :: t
        character(len=:), allocatable :: para_x, para_y
        integer, allocatable :: rows(:)
        integer :: cx, cy, k, n
        if (cmd%has('NOM_PARA_TABL')) then
            call cmd%error_at('NOM_PARA_TABL', 'tables of functions are not built by ' // &
                'parasol: give PARA_X and PARA_Y', st, STATUS_NOT_IMPLEMENTED)
            return
        end if
        if (.not. cmd%has('PARA_X')) then
            call cmd%error_at('TABLE', 'give PARA_X and PARA_Y, the columns of the ' // &
                'abscissae and of the ordinates', st)
            return
        end if
        call table_of_keyword(cmd, 'TABLE', t, st)
        if (st%ok()) call cmd%get_text('PARA_X', para_x, st)
        if (st%ok()) call cmd%get_text('PARA_Y', para_y, st)
        if (st%failed()) return
        call filter_rows_of_command(cmd, 'FILTRE', t, .true., .true., rows, st)
        if (st%failed()) return
        call numeric_column(para_x, 'PARA_X', cx)
        if (st%ok()) call numeric_column(para_y, 'PARA_Y', cy)
        if (st%failed()) return
        rows = pack(rows, t%columns(cx)%present(rows) .and. t%columns(cy)%present(rows))
        n = size(rows)
        if (n == 0) then
            call cmd%error_at('PARA_Y', 'no row of table ' // concept_display_name(t) // &
                ' holds both ' // para_x // ' and ' // para_y, st, STATUS_MODEL_ERROR)
            return
        end if
        allocate (f%x(n), f%y(n))
        do k = 1, n
            f%x(k) = table_cell_real(t, cx, rows(k))
            f%y(k) = table_cell_real(t, cy, rows(k))
        end do
        f%parameter = para_x
        f%result_name = para_y
    contains
        subroutine numeric_column(name, key, column)
            character(len=*), intent(in) :: name, key
            integer, intent(out) :: column
            call table_require_column(t, name, column, st)
            if (st%failed()) then
                call relocate_at(cmd, key, st)
                return
            end if
            if (.not. table_is_number(t%columns(column))) call cmd%error_at(key, 'column ' // &
                name // ' holds texts (' // table_kind_label(t%columns(column)) // &
                '): a function takes numbers', st)
        end subroutine numeric_column
    end subroutine function_from_table

    !> RESULTAT with NOM_CHAM (a component at a node or a cell's point) or NOM_PARA_RESU.
    subroutine function_from_result(ctx, cmd, f, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(tabulated_function_t), intent(inout) :: f
        type(status_t), intent(inout) :: st
        class(result_fields_t), pointer :: res
        type(field_t), pointer :: field
        type(mesh_t), pointer :: mesh
        character(len=:), allocatable :: name, component, parameter
        integer, allocatable :: indices(:)
        integer :: k
        logical :: by_inst
        type(place_t) :: place
        call result_of_occurrence(cmd, res, st)
        if (st%failed()) return
        if (cmd%has('INTERP_NUME')) then
            call cmd%get_text('INTERP_NUME', name, st)
            if (st%failed()) return
            if (name /= 'NON') then
                call cmd%error_at('INTERP_NUME', 'INTERP_NUME=''LIN'' (values between ' // &
                    'stored instants) is not built by parasol: the function takes the ' // &
                    'stored instants', st, STATUS_NOT_IMPLEMENTED)
                return
            end if
        end if
        call selected_instants(cmd, res, indices, by_inst, st)
        if (st%failed()) return
        indices = storage_order(indices)
        allocate (f%x(size(indices)), f%y(size(indices)))
        f%x = res%inst(indices)
        f%parameter = 'INST'
        if (cmd%has('NOM_PARA_RESU')) then
            call cmd%get_text('NOM_PARA_RESU', parameter, st)
            if (st%failed()) return
            if (parameter /= 'INST') then
                call cmd%error_at('NOM_PARA_RESU', 'the result stores no parameter ' // &
                    parameter // ' (parasol''s results store INST)', st, STATUS_MODEL_ERROR)
                return
            end if
            f%y = f%x
            f%result_name = parameter
            return
        end if
        if (.not. (cmd%has('NOM_CHAM') .and. cmd%has('NOM_CMP'))) then
            call cmd%error_at('RESULTAT', 'give NOM_CHAM and NOM_CMP (or NOM_PARA_RESU)', st)
            return
        end if
        if (cmd%has('NOM_VARI')) then
            call cmd%error_at('NOM_VARI', 'internal variables by name are not read by ' // &
                'parasol: give their component V1, V2, ... in NOM_CMP', st, &
                STATUS_NOT_IMPLEMENTED)
            return
        end if
        call cmd%get_text('NOM_CHAM', name, st)
        if (st%ok()) call cmd%get_text('NOM_CMP', component, st)
        if (st%failed()) return
        call result_mesh(res, mesh, st)
        if (st%failed()) then
            call relocate_at(cmd, 'RESULTAT', st)
            return
        end if
        f%result_name = component
        do k = 1, size(indices)
            call result_field_at(res, int(indices(k), i4), name, field, st)
            if (st%failed()) then
                call relocate_at(cmd, 'NOM_CHAM', st)
                return
            end if
            if (k == 1) call locate(ctx, cmd, field, mesh, place, st)
            if (st%failed()) return
            call value_at(cmd, field, place, component, f%y(k), st)
            if (st%failed()) then
                st%message = 'INST ' // real_e13(res%inst(indices(k))) // ': ' // st%message
                return
            end if
        end do
    end subroutine function_from_result

    !> The stored fields selected, each once, in storage order (Code_Aster's rsutnu merges
    !> the order numbers it finds into a sorted list, whatever order INST lists them in).
    pure function storage_order(indices) result(sorted)
        integer, intent(in) :: indices(:)
        integer, allocatable :: sorted(:)
        logical, allocatable :: chosen(:)
        integer :: k
        allocate (chosen(max(0, maxval(indices, dim=1))), source=.false.)
        do k = 1, size(indices)
            chosen(indices(k)) = .true.
        end do
        sorted = pack([(k, k=1, size(chosen))], chosen)
    end function storage_order

    !> Where in the field the function is read: a node, or a cell with its point and
    !> sub-point.
    subroutine locate(ctx, cmd, field, mesh, place, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(field_t), intent(in) :: field
        type(mesh_t), intent(in) :: mesh
        type(place_t), intent(out) :: place
        type(status_t), intent(inout) :: st
        integer(i4) :: k
        if (cmd%has('GROUP_NO') .or. cmd%has('NOEUD')) then
            call one_entity(ctx, cmd, mesh, .true., place%node, st)
            if (st%failed()) return
        end if
        if (.not. field_is_cell_field(field)) then
            if (place%node == 0) then
                call cmd%error_at('NOM_CHAM', 'the field is a nodal field: give NOEUD or ' // &
                    'GROUP_NO', st)
                return
            end if
            if (cmd%has('POINT')) call cmd%error_at('POINT', 'POINT goes with element ' // &
                'fields; the field is a nodal field', st)
            return
        end if
        if (.not. (cmd%has('GROUP_MA') .or. cmd%has('MAILLE'))) then
            call cmd%error_at('NOM_CHAM', 'the field is an element field: give GROUP_MA ' // &
                '(or MAILLE) and POINT (ELNO: or the cell''s NOEUD / GROUP_NO)', st)
            return
        end if
        call one_entity(ctx, cmd, mesh, .false., place%cell, st)
        if (st%failed()) return
        place%point = 1
        place%subpoint = 1
        if (cmd%has('POINT')) call cmd%get_int('POINT', place%point, st)
        if (st%ok() .and. cmd%has('SOUS_POINT')) call cmd%get_int('SOUS_POINT', place%subpoint, st)
        if (st%failed()) return
        if (field%location == FIELD_ELNO .and. place%node > 0) then
            if (cmd%has('POINT')) then
                call cmd%error_at('POINT', 'give the node of the cell (NOEUD, GROUP_NO) or ' // &
                    'POINT, not both', st)
                return
            end if
            place%point = 0
            do k = mesh%cell_ptr(place%cell), mesh%cell_ptr(place%cell + 1) - 1
                if (mesh%cell_nodes(k) == place%node) place%point = k - &
                    mesh%cell_ptr(place%cell) + 1
            end do
            if (place%point == 0) call cmd%error_at(trim(merge('GROUP_NO', 'NOEUD   ', &
                cmd%has('GROUP_NO'))), 'node ' // node_name(mesh, place%node) // &
                ' is not a node of cell ' // cell_name(mesh, place%cell), st)
        else if (place%node > 0) then
            call cmd%error_at(trim(merge('GROUP_NO', 'NOEUD   ', cmd%has('GROUP_NO'))), &
                'a node goes with nodal and ELNO fields; this one is at ' // &
                'Gauss points or per cell: give POINT', st)
        end if
    end subroutine locate

    !> The node (nodes) or cell of NOEUD / GROUP_NO or MAILLE / GROUP_MA: a group's first
    !> member, with a warning when it has several.
    subroutine one_entity(ctx, cmd, mesh, nodes, entity, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(mesh_t), intent(in) :: mesh
        logical, intent(in) :: nodes
        integer, intent(out) :: entity
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: key, name
        integer(i4), allocatable :: members(:)
        integer(i4) :: g
        entity = 0
        if (nodes) then
            key = 'NOEUD'
            if (cmd%has('GROUP_NO')) key = 'GROUP_NO'
        else
            key = 'MAILLE'
            if (cmd%has('GROUP_MA')) key = 'GROUP_MA'
        end if
        call cmd%get_text(key, name, st)
        if (st%failed()) return
        select case (key)
        case ('NOEUD')
            entity = find_node(mesh, name, st)
        case ('MAILLE')
            entity = find_cell(mesh, name, st)
        case ('GROUP_NO')
            g = find_node_group(mesh, name, st)
            if (st%ok()) members = nodes_of_group(mesh, g)
        case default
            g = find_cell_group(mesh, name, st)
            if (st%ok()) members = cells_of_group(mesh, g)
        end select
        if (st%failed()) then
            call relocate_at(cmd, key, st)
            return
        end if
        if (.not. allocated(members)) return
        if (size(members) == 0) then
            call cmd%error_at(key, key // ' ' // name // ' is empty', st, STATUS_MODEL_ERROR)
            return
        end if
        entity = members(1)
        if (size(members) > 1) then
            if (nodes) then
                call warn_at(ctx, cmd, key, key // ' ' // name // ' holds ' // &
                    to_text(size(members, kind=i4)) // ' nodes: the function is read at ' // &
                    'its first, ' // node_name(mesh, members(1)))
            else
                call warn_at(ctx, cmd, key, key // ' ' // name // ' holds ' // &
                    to_text(size(members, kind=i4)) // ' cells: the function is read at ' // &
                    'its first, ' // cell_name(mesh, members(1)))
            end if
        end if
    end subroutine one_entity

    !> The component at the place.
    subroutine value_at(cmd, field, place, component, value, st)
        type(command_t), intent(in) :: cmd
        type(field_t), intent(in) :: field
        type(place_t), intent(in) :: place
        character(len=*), intent(in) :: component
        real(dp), intent(out) :: value
        type(status_t), intent(inout) :: st
        if (field%location == FIELD_NOEU) then
            call field_node_value(field, int(place%node, i4), component, value, st)
        else
            call field_cell_value(field, int(place%cell, i4), int(place%point, i4), &
                                  int(place%subpoint, i4), component, value, st)
        end if
        if (st%failed()) call relocate_at(cmd, 'NOM_CMP', st)
    end subroutine value_at

    !> Orders the points by abscissa as Code_Aster's ordonn: strictly decreasing ones are
    !> reversed, others sorted (with a warning at `key`); a repeated abscissa is an error.
    subroutine order_abscissae(ctx, cmd, key, x, y, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        character(len=*), intent(in) :: key
        real(dp), intent(inout) :: x(:), y(:)
        type(status_t), intent(inout) :: st
        integer, allocatable :: order(:)
        integer :: k, n
        n = size(x)
        if (n < 2) return
        if (all(x(2:) > x(:n - 1))) return
        if (all(x(2:) < x(:n - 1))) then
            x = x(n:1:-1)
            y = y(n:1:-1)
            call warn_at(ctx, cmd, key, 'the abscissae decrease: the function''s points ' // &
                'are taken in the reverse order')
            return
        end if
        order = real_order(x)
        x = x(order)
        y = y(order)
        do k = 2, n
            if (.not. x(k) > x(k - 1)) then
                call cmd%error_at(key, 'the abscissa ' // real_e13(x(k)) // ' is given ' // &
                    'twice: a function takes one ordinate per abscissa', st, STATUS_MODEL_ERROR)
                return
            end if
        end do
        call warn_at(ctx, cmd, key, 'the abscissae are not in increasing order: the ' // &
            'function''s points are sorted')
    end subroutine order_abscissae

    !> NOM_PARA, NOM_RESU, INTERPOL, PROL_GAUCHE, PROL_DROITE given to the command.
    subroutine set_function_attributes(cmd, f, st)
        type(command_t), intent(in) :: cmd
        type(tabulated_function_t), intent(inout) :: f
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: text
        type(string_t), allocatable :: interpol(:)
        if (cmd%has('NOM_PARA')) call cmd%get_text('NOM_PARA', f%parameter, st)
        if (st%ok() .and. cmd%has('NOM_RESU')) call cmd%get_text('NOM_RESU', f%result_name, st)
        if (st%ok() .and. cmd%has('INTERPOL')) then
            call cmd%get_texts('INTERPOL', interpol, st)
            if (st%ok()) then
                if (interpol(1)%s == 'LOG' .or. interpol(size(interpol))%s == 'LOG') &
                    call cmd%error_at('INTERPOL', 'logarithmic interpolation is not built ' // &
                    'by parasol (INTERPOL=''LIN'' is)', st, STATUS_NOT_IMPLEMENTED)
            end if
        end if
        if (st%ok() .and. cmd%has('PROL_GAUCHE')) then
            call cmd%get_text('PROL_GAUCHE', text, st)
            f%left = prolongation_code(text)
        end if
        if (st%ok() .and. cmd%has('PROL_DROITE')) then
            call cmd%get_text('PROL_DROITE', text, st)
            f%right = prolongation_code(text)
        end if
    end subroutine set_function_attributes

end module recu_fonction_command
