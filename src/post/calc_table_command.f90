!> CALC_TABLE (U4.33.03): a sequence of ACTION on a copy of TABLE, as Code_Aster's
!> calc_table_ops runs them, then the new table stored as Code_Aster stores it (columns
!> and rows without any value dropped, a note in the .mess for each dropped column):
!>   FILTRE         rows passing NOM_PARA CRIT_COMP VALE/VALE_I/VALE_K (table_filter,
!>                  Python rules; REGEXP too)
!>   EXTR           the columns NOM_PARA, in that order
!>   SUPPRIME       without the columns NOM_PARA (one it lacks is a warning)
!>   RENOMME        NOM_PARA = (old name, new name)
!>   TRI            rows ordered on NOM_PARA, ORDRE
!>   COMB           with TABLE, on the keys NOM_PARA (table_operations), RESTREINT, FORMAT_R
!>   AJOUT_LIGNE    a row: VALE(k) in NOM_PARA(k)
!>   AJOUT_COLONNE  columns NOM_PARA of constant VALE, or one column of values VALE_COLONNE
!>   OPER           a column NOM_PARA = FORMULE of its parameters (or of NOM_COLONNE)
!>   UNIQUE         the first row of each value of NOM_PARA
!>   STATISTIQUES   STAT_NOM / STAT_VALE: numbers of rows, columns, absent cells
!>   CALCUL         a table of NOM_PARA reduced by each TYPE_CALCUL
!> Each OPERATION takes its own keywords (Code_Aster's catalog blocks): another keyword
!> given in its ACTION is an error naming those it takes. The result's title is TITRE, or
!> the default title naming the input table (Code_Aster's get_titre_concept(TABLE)).
!> INFO=2 writes the table's size after each action to the .mess.
module calc_table_command
    use kinds, only: i4
    use strings, only: string_t, to_text, join_words
    use status, only: status_t
    use python_format, only: real_format_t, parse_real_format
    use deck_concept, only: concept_t, concept_display_name
    use deck_command, only: command_t, keyword_set_t
    use deck_value, only: value_t
    use run_context, only: run_context_t
    use function_concept, only: function_concept_t
    use table_concept, only: table_label, table_t, table_select_rows, table_select_columns, &
        table_require_column, table_find_column, table_rename_column, table_append_title, &
        table_default_title, table_replace_rows
    use table_sort, only: table_sorted_rows
    use table_filter, only: table_filter_t, apply_table_filter
    use table_keywords, only: table_of_keyword, read_filter, relocate_at, read_mixed_values, &
        filter_keyword, warn_at
    use table_operations, only: table_combine, table_unique_rows, table_drop_empty_columns, &
        table_append_row, table_add_value_column, table_add_formula_column, &
        table_add_statistics, table_calculation
    implicit none
    private

    public :: run_calc_table

contains

    !> Handler of CALC_TABLE.
    subroutine run_calc_table(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(table_t), pointer :: source
        type(table_t), allocatable :: t
        type(keyword_set_t) :: occ
        type(string_t), allocatable :: dropped(:), titles(:)
        character(len=:), allocatable :: operation
        integer :: k, info
        call table_of_keyword(cmd, 'TABLE', source, st)
        if (st%ok()) call cmd%get_int('INFO', info, st)
        if (st%failed()) return
        allocate (t)
        t = table_select_rows(source, [(k, k=1, source%n_rows)])
        t%name = concept_display_name(source)      ! messages name the table worked on
        deallocate (t%title)
        allocate (t%title(0))
        call table_append_title(t, table_default_title(source))
        do k = 1, cmd%count('ACTION')
            occ = cmd%occurrence('ACTION', k)
            call occ%get_text('OPERATION', operation, st)
            if (st%failed()) return
            call check_operation_keywords(occ, operation, st)
            if (st%failed()) return
            call run_action(ctx, occ, operation, t, st)
            if (st%failed()) return
            if (info == 2) call ctx%write_mess('    CALC_TABLE ACTION ' // &
                to_text(int(k, i4)) // ' (' // operation // '): ' // &
                to_text(int(t%n_rows, i4)) // ' rows, ' // to_text(int(t%n_columns, i4)) // &
                ' columns')
        end do
        call table_drop_empty_columns(t, dropped)
        if (size(dropped) > 0) call ctx%write_mess('    CALC_TABLE: columns without any ' // &
            'value are not kept (as Code_Aster): ' // join_words(dropped, ', '))
        if (cmd%has('TITRE')) then
            call cmd%get_texts('TITRE', titles, st)
            if (st%failed()) return
            deallocate (t%title)
            allocate (t%title(0))
            do k = 1, size(titles)
                call table_append_title(t, titles(k)%s)
            end do
        end if
        call move_alloc(t, result)
    end subroutine run_calc_table

    !> The keywords each OPERATION takes (Code_Aster's blocks) and those it needs.
    subroutine check_operation_keywords(occ, operation, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: operation
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: allowed, required
        integer :: k
        select case (operation)
        case ('FILTRE')
            allowed = 'NOM_PARA CRIT_COMP VALE VALE_I VALE_K CRITERE PRECISION'
            required = 'NOM_PARA'
        case ('EXTR', 'SUPPRIME')
            allowed = 'NOM_PARA'
            required = 'NOM_PARA'
        case ('UNIQUE')
            allowed = 'NOM_PARA FORMAT_R'
            required = 'NOM_PARA'
        case ('RENOMME')
            allowed = 'NOM_PARA'
            required = 'NOM_PARA'
        case ('TRI')
            allowed = 'NOM_PARA ORDRE'
            required = 'NOM_PARA'
        case ('COMB')
            allowed = 'TABLE NOM_PARA RESTREINT FORMAT_R'
            required = 'TABLE'
        case ('AJOUT_LIGNE')
            allowed = 'NOM_PARA VALE'
            required = 'NOM_PARA VALE'
        case ('AJOUT_COLONNE')
            allowed = 'NOM_PARA VALE VALE_COLONNE'
            required = 'NOM_PARA'
        case ('OPER')
            allowed = 'FORMULE NOM_PARA NOM_COLONNE'
            required = 'FORMULE NOM_PARA'
        case ('CALCUL')
            allowed = 'NOM_PARA TYPE_CALCUL'
            required = 'NOM_PARA TYPE_CALCUL'
        case default
            allowed = ''
            required = ''
        end select
        do k = 1, occ%n
            if (occ%items(k)%name == 'OPERATION' .or. occ%items(k)%is_default) cycle
            if (index(' ' // allowed // ' ', ' ' // occ%items(k)%name // ' ') > 0) cycle
            if (len(allowed) == 0) allowed = 'no other keyword'
            call occ%error_at(occ%items(k)%name, 'OPERATION=''' // operation // ''' takes ' // &
                allowed // ', not ' // occ%items(k)%name, st)
            return
        end do
        call require_each(required)
        if (st%failed()) return
        if (operation == 'AJOUT_COLONNE' .and. (occ%has('VALE') .eqv. occ%has('VALE_COLONNE'))) &
            call occ%error_at('NOM_PARA', 'OPERATION=''AJOUT_COLONNE'' takes VALE (a ' // &
            'constant per column) or VALE_COLONNE (the values of one column): one of them', st)
    contains
        subroutine require_each(names)
            character(len=*), intent(in) :: names
            integer :: i, j
            character(len=:), allocatable :: name
            i = 1
            do while (i <= len(names))
                j = index(names(i:) // ' ', ' ') + i - 1
                name = names(i:j - 1)
                if (.not. occ%has(name)) then
                    call occ%error_at('OPERATION', 'OPERATION=''' // operation // &
                        ''' needs ' // name, st)
                    return
                end if
                i = j + 1
            end do
        end subroutine require_each
    end subroutine check_operation_keywords

    !> One action on `t`.
    subroutine run_action(ctx, occ, operation, t, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: operation
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: names(:)
        type(table_t) :: out
        type(table_t), pointer :: other
        type(table_filter_t) :: f
        type(real_format_t) :: format_r
        character(len=:), allocatable :: text, name
        integer, allocatable :: rows(:), columns(:)
        type(value_t), allocatable :: values(:)
        class(concept_t), pointer :: formula
        integer :: k
        if (occ%has('NOM_PARA')) call occ%get_texts('NOM_PARA', names, st)
        if (st%failed()) return
        if (occ%has('FORMAT_R')) then
            call occ%get_text('FORMAT_R', text, st)
            if (st%ok()) call parse_real_format(text, format_r, st)
            if (st%failed()) then
                call relocate_at(occ, 'FORMAT_R', st)
                return
            end if
        end if
        if (allocated(t%name)) name = t%name
        select case (operation)
        case ('FILTRE')
            call read_filter(occ, .false., f, st)
            if (st%failed()) return
            rows = [(k, k=1, t%n_rows)]
            call apply_table_filter(t, f, rows, st)
            if (st%failed()) then
                call relocate_at(occ, filter_keyword(occ, st%message), st)
                return
            end if
            call table_replace_rows(t, rows)
        case ('EXTR')
            allocate (columns(size(names)))
            do k = 1, size(names)
                call table_require_column(t, names(k)%s, columns(k), st)
                if (st%failed()) then
                    call relocate_at(occ, 'NOM_PARA', st)
                    return
                end if
            end do
            out = table_select_columns(t, columns)
            t = out
        case ('SUPPRIME')
            do k = 1, size(names)
                if (table_find_column(t, names(k)%s) == 0) &
                    call warn_at(ctx, occ, 'NOM_PARA', table_label(t) // &
                    ' has no column ' // names(k)%s // ': nothing to remove')
            end do
            columns = kept_columns(t, names)
            out = table_select_columns(t, columns)
            t = out
        case ('RENOMME')
            if (size(names) /= 2) then
                call occ%error_at('NOM_PARA', 'OPERATION=''RENOMME'' takes NOM_PARA=(old ' // &
                    'name, new name): 2 names, not ' // to_text(int(size(names), i4)), st)
                return
            end if
            call table_rename_column(t, names(1)%s, names(2)%s, st)
            if (st%failed()) call relocate_at(occ, 'NOM_PARA', st)
        case ('TRI')
            call occ%get_text('ORDRE', text, st)
            if (st%failed()) return
            allocate (columns(size(names)))
            do k = 1, size(names)
                call table_require_column(t, names(k)%s, columns(k), st)
                if (st%failed()) then
                    call relocate_at(occ, 'NOM_PARA', st)
                    return
                end if
            end do
            call table_sorted_rows(t, columns, text == 'DECROISSANT', rows)
            call table_replace_rows(t, rows)
        case ('COMB')
            call table_of_keyword(occ, 'TABLE', other, st)
            if (st%ok()) call occ%get_text('RESTREINT', text, st)
            if (st%failed()) return
            if (.not. allocated(names)) allocate (names(0))
            if (occ%has('FORMAT_R')) then
                call table_combine(t, other, names, text == 'OUI', out, st, format_r)
            else
                call table_combine(t, other, names, text == 'OUI', out, st)
            end if
            if (st%failed()) then
                call relocate_at(occ, merge('NOM_PARA', 'TABLE   ', occ%has('NOM_PARA')), st)
                return
            end if
            t = out
        case ('AJOUT_LIGNE')
            call read_mixed_values(occ, 'VALE', values)
            if (size(values) /= size(names)) then
                call occ%error_at('VALE', 'VALE has ' // to_text(int(size(values), i4)) // &
                    ' values for ' // to_text(int(size(names), i4)) // ' NOM_PARA (one each)', &
                    st)
                return
            end if
            call table_append_row(t, names, values, st)
            if (st%failed()) call relocate_at(occ, 'VALE', st)
        case ('AJOUT_COLONNE')
            if (occ%has('VALE_COLONNE')) then
                if (size(names) /= 1) then
                    call occ%error_at('NOM_PARA', 'VALE_COLONNE gives the values of one ' // &
                        'column: give one NOM_PARA, not ' // to_text(int(size(names), i4)), st)
                    return
                end if
                call read_mixed_values(occ, 'VALE_COLONNE', values)
                call table_add_value_column(t, names(1)%s, values, .false., st)
                if (st%failed()) call relocate_at(occ, 'VALE_COLONNE', st)
            else
                call read_mixed_values(occ, 'VALE', values)
                if (size(values) /= size(names)) then
                    call occ%error_at('VALE', 'VALE has ' // to_text(int(size(values), i4)) &
                        // ' values for ' // to_text(int(size(names), i4)) // &
                        ' NOM_PARA (one constant per column)', st)
                    return
                end if
                do k = 1, size(names)
                    call table_add_value_column(t, names(k)%s, values(k:k), .true., st)
                    if (st%failed()) then
                        call relocate_at(occ, 'VALE', st)
                        return
                    end if
                end do
            end if
        case ('OPER')
            call occ%get_concept('FORMULE', formula, st)
            if (st%failed()) return
            if (size(names) /= 1) then
                call occ%error_at('NOM_PARA', 'OPERATION=''OPER'' makes one column: give ' // &
                    'one NOM_PARA', st)
                return
            end if
            call oper_action(occ, formula, names(1)%s, t, st)
        case ('UNIQUE')
            if (occ%has('FORMAT_R')) then
                call table_unique_rows(t, names, st, format_r)
            else
                call table_unique_rows(t, names, st)
            end if
            if (st%failed()) call relocate_at(occ, 'NOM_PARA', st)
        case ('STATISTIQUES')
            call table_add_statistics(t, st)
            if (st%failed()) call relocate_at(occ, 'OPERATION', st)
        case ('CALCUL')
            call calcul_action(occ, names, t, st)
        end select
        if (allocated(name)) t%name = name
    end subroutine run_action

    !> OPER: the formula's parameters are its own NOM_PARA, or NOM_COLONNE in order.
    subroutine oper_action(occ, formula, name, t, st)
        type(keyword_set_t), intent(in) :: occ
        class(concept_t), intent(in) :: formula
        character(len=*), intent(in) :: name
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: parameters(:)
        select type (formula)
        class is (function_concept_t)
            parameters = formula%parameters()
            if (occ%has('NOM_COLONNE')) then
                call occ%get_texts('NOM_COLONNE', parameters, st)
                if (st%failed()) return
                if (size(parameters) /= size(formula%parameters())) then
                    call occ%error_at('NOM_COLONNE', 'the formula has ' // &
                        to_text(int(size(formula%parameters()), i4)) // ' parameters: ' // &
                        'NOM_COLONNE names one column per parameter, not ' // &
                        to_text(int(size(parameters), i4)), st)
                    return
                end if
            end if
            call table_add_formula_column(t, name, formula, parameters, st)
            if (st%failed()) call relocate_at(occ, 'FORMULE', st)
        class default
            call occ%error_at('FORMULE', 'expected a formula', st)
        end select
    end subroutine oper_action

    !> CALCUL: the table becomes the reductions of its numeric columns NOM_PARA.
    subroutine calcul_action(occ, names, t, st)
        type(keyword_set_t), intent(in) :: occ
        type(string_t), intent(in) :: names(:)
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: operations(:)
        type(table_t) :: out
        call occ%get_texts('TYPE_CALCUL', operations, st)
        if (st%failed()) return
        call table_calculation(t, names, operations, out, st)
        if (st%failed()) then
            call relocate_at(occ, 'NOM_PARA', st)
            return
        end if
        out%title = t%title
        t = out
    end subroutine calcul_action

    !> The columns of `t` whose names are not in `names`.
    function kept_columns(t, names) result(columns)
        type(table_t), intent(in) :: t
        type(string_t), intent(in) :: names(:)
        integer, allocatable :: columns(:)
        integer :: c, k
        logical :: removed
        allocate (columns(0))
        do c = 1, t%n_columns
            removed = .false.
            do k = 1, size(names)
                if (t%columns(c)%name == names(k)%s) removed = .true.
            end do
            if (.not. removed) columns = [columns, c]
        end do
    end function kept_columns


end module calc_table_command
