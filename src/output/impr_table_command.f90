!> IMPR_TABLE (U4.91.03): writes a table, as Code_Aster's impr_table_ops does:
!>  1. FILTRE occurrences keep rows (Python rules, table_filter); each is traced in the
!>     title (`FILTRE -> NOM_PARA: ... CRIT_COMP: ... VALE: ...`);
!>  2. TRI orders the rows (stable, table_sort);
!>  3. NOM_PARA chooses the columns and their order (a column the table lacks is a warning,
!>     as Code_Aster's alarm TABLE0_7); columns without any value are left out;
!>  4. PAGINATION writes one table per combination of the values of its columns;
!>  5. the text (table_listing: FORMAT TABLEAU, ASTER, AGRAF; TABLEAU_CROISE crosses a
!>     table of three columns) goes to UNITE (unit_text_output: 8 = the .resu).
!> Title: TITRE, then the table's own title (by default `CONCEPT <name> CALCULE DE TYPE
!> TABLE_SDASTER`, Code_Aster's words without its version and date, so listings stay
!> deterministic), then the filters. SEPARATEUR defaults to one blank, FIN_LIGNE to a new
!> line (Code_Aster's defaults, applied here since they are not lists of words).
!> FORMAT='XMGRACE' (a plot) and 'NUMPY' (a binary array) are not written by parasol:
!> a located error says so.
module impr_table_command
    use kinds, only: i4, dp
    use progress, only: wall_seconds
    use strings, only: string_t, to_text
    use status, only: status_t, STATUS_NOT_IMPLEMENTED, STATUS_MODEL_ERROR
    use python_format, only: float_repr, parse_real_format
    use deck_concept, only: concept_t, concept_display_name
    use deck_command, only: command_t, keyword_set_t
    use deck_value, only: append_string
    use run_context, only: run_context_t
    use table_concept, only: table_t, table_find_column, table_select_rows, table_init, &
        table_add_column, table_add_rows, table_copy_cell, TABLE_TEXT, TABLE_INT, &
        table_cell_text, table_cell_real, table_default_title
    use table_sort, only: table_sorted_rows, compare_table_rows
    use table_filter, only: table_filter_t
    use table_keywords, only: table_of_keyword, filter_rows_of_command, read_filter, &
        relocate_at, warn_at
    use table_listing, only: table_layout_t, default_table_layout, &
        table_text_lines
    use unit_text_output, only: write_unit_text
    implicit none
    private

    public :: run_impr_table

contains

    !> Handler of IMPR_TABLE.
    !>  st : located errors: not a table, a filter on a column that does not exist (naming
    !>       those that do) or of another type, a TRI or PAGINATION column that does not
    !>       exist, a FORMAT_R that is not a real format, TABLEAU_CROISE on other than three
    !>       columns, an unwritable file
    subroutine run_impr_table(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(table_t), pointer :: t
        type(table_t) :: selected
        type(table_layout_t) :: layout
        type(string_t), allocatable :: title(:), lines(:), pages(:)
        integer, allocatable :: rows(:), columns(:)
        character(len=:), allocatable :: format, where
        integer :: unit
        real(dp) :: start
        start = wall_seconds()
        if (allocated(result)) deallocate (result)
        call table_of_keyword(cmd, 'TABLE', t, st)
        if (st%ok()) call cmd%get_text('FORMAT', format, st)
        if (st%ok()) call cmd%get_int('UNITE', unit, st)
        if (st%failed()) return
        if (format == 'XMGRACE' .or. format == 'NUMPY') then
            call cmd%error_at('FORMAT', 'FORMAT=''' // format // ''' is not written by ' // &
                'parasol (TABLEAU, ASTER, AGRAF and TABLEAU_CROISE are)', st, &
                STATUS_NOT_IMPLEMENTED)
            return
        end if
        call read_layout(cmd, format, layout, st)
        if (st%failed()) return
        call filter_rows_of_command(cmd, 'FILTRE', t, .false., .false., rows, st)
        if (st%failed()) return
        selected = table_select_rows(t, rows)
        if (allocated(t%name)) selected%name = t%name
        call sort_by_tri(cmd, selected, st)
        if (st%failed()) return
        call title_lines(cmd, t, title, st)
        if (st%failed()) return
        call printed_columns(ctx, cmd, selected, columns)
        allocate (pages(0))
        if (cmd%has('PAGINATION')) call cmd%get_texts('PAGINATION', pages, st)
        if (st%failed()) return
        if (format == 'TABLEAU_CROISE') then
            call crossed_lines(cmd, selected, columns, title, layout, lines, st)
        else if (size(pages) > 0) then
            call paged_lines(cmd, selected, columns, pages, title, layout, lines, st)
        else
            call table_text_lines(selected, columns, all_rows(selected), title, layout, lines)
        end if
        if (st%failed()) return
        call write_unit_text(ctx, unit, lines, where, st, cmd, 'UNITE')
        if (st%failed()) return
        call ctx%write_mess('    IMPR_TABLE: ' // concept_display_name(t) // ' (' // &
            to_text(int(selected%n_rows, i4)) // ' rows, ' // &
            to_text(int(size(columns), i4)) // ' columns, FORMAT ' // format // ') -> ' // &
            where // ', ' // trim(seconds_of(wall_seconds() - start)) // ' s')
    end subroutine run_impr_table

    !> Seconds as text (three decimals).
    function seconds_of(seconds) result(text)
        real(dp), intent(in) :: seconds
        character(len=32) :: text
        write (text, '(f0.3)') seconds
    end function seconds_of

    !> 1, 2, ..., n_rows.
    pure function all_rows(t) result(rows)
        type(table_t), intent(in) :: t
        integer, allocatable :: rows(:)
        integer :: r
        rows = [(r, r=1, t%n_rows)]
    end function all_rows

    !> The layout keywords (defaults of Code_Aster's catalog).
    subroutine read_layout(cmd, format, layout, st)
        type(command_t), intent(in) :: cmd
        character(len=*), intent(in) :: format
        type(table_layout_t), intent(out) :: layout
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: text
        layout = default_table_layout()
        layout%format = format
        if (format == 'TABLEAU_CROISE') layout%format = 'TABLEAU'
        call cmd%get_text('FORMAT_R', text, st)
        if (st%failed()) return
        call parse_real_format(text, layout%real_format, st)
        if (st%failed()) then
            call relocate_at(cmd, 'FORMAT_R', st)
            return
        end if
        if (format == 'AGRAF' .and. .not. cmd%given('FORMAT_R')) then
            ! Code_Aster's impr_table_ops: AGRAF writes reals in %12.5E whatever FORMAT_R
            call parse_real_format('E12.5', layout%real_format, st)
        end if
        if (cmd%has('DEBUT_TABLE')) then
            layout%has_heading = .true.
            call cmd%get_text('DEBUT_TABLE', layout%heading, st)
        end if
        if (st%ok() .and. cmd%has('FIN_TABLE')) call cmd%get_text('FIN_TABLE', layout%footer, st)
        if (st%ok() .and. cmd%has('SEPARATEUR')) &
            call cmd%get_text('SEPARATEUR', layout%separator, st)
        if (st%ok()) call cmd%get_text('COMMENTAIRE', layout%comment, st)
        if (st%ok() .and. cmd%has('COMM_PARA')) &
            call cmd%get_text('COMM_PARA', layout%names_prefix, st)
        if (st%ok() .and. cmd%has('DEBUT_LIGNE')) &
            call cmd%get_text('DEBUT_LIGNE', layout%line_start, st)
        if (st%ok() .and. cmd%has('FIN_LIGNE')) call cmd%get_text('FIN_LIGNE', layout%line_end, st)
    end subroutine read_layout

    !> TITRE, the table's title (or its default), the filters.
    subroutine title_lines(cmd, t, title, st)
        type(command_t), intent(in) :: cmd
        type(table_t), intent(in) :: t
        type(string_t), allocatable, intent(out) :: title(:)
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: given(:)
        type(table_filter_t) :: f
        integer :: k
        allocate (title(0))
        if (cmd%has('TITRE')) then
            call cmd%get_texts('TITRE', given, st)
            if (st%failed()) return
            do k = 1, size(given)
                call append_string(title, given(k)%s)
            end do
        end if
        if (size(t%title) == 0) then
            call append_string(title, table_default_title(t))
        else
            do k = 1, size(t%title)
                call append_string(title, t%title(k)%s)
            end do
        end if
        do k = 1, cmd%count('FILTRE')
            call read_filter(cmd%occurrence('FILTRE', k), .false., f, st)
            if (st%failed()) return
            call append_string(title, filter_trace(f))
        end do
    end subroutine title_lines

    !> `FILTRE -> NOM_PARA: <16 wide> CRIT_COMP: <4 wide> VALE: <values>` (impr_table_ops).
    function filter_trace(f) result(text)
        type(table_filter_t), intent(in) :: f
        character(len=:), allocatable :: text
        integer :: k
        text = 'FILTRE -> NOM_PARA: ' // pad(f%column, 16) // ' CRIT_COMP: ' // &
            pad(f%operation, 4) // ' VALE:'
        if (allocated(f%reals)) then
            do k = 1, size(f%reals)
                text = text // ' ' // float_repr(f%reals(k))
            end do
        end if
        if (allocated(f%ints)) then
            do k = 1, size(f%ints)
                text = text // ' ' // to_text(f%ints(k))
            end do
        end if
        if (allocated(f%texts)) then
            do k = 1, size(f%texts)
                text = text // ' ' // f%texts(k)%s
            end do
        end if
    end function filter_trace

    pure function pad(text, width) result(out)
        character(len=*), intent(in) :: text
        integer, intent(in) :: width
        character(len=:), allocatable :: out
        out = text // repeat(' ', max(width - len(text), 0))
    end function pad

    !> TRI: the rows of `t` reordered on the NOM_PARA keys.
    subroutine sort_by_tri(cmd, t, st)
        type(command_t), intent(in) :: cmd
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        type(keyword_set_t) :: occ
        type(string_t), allocatable :: names(:)
        character(len=:), allocatable :: order_text, name
        integer, allocatable :: keys(:), order(:)
        integer :: k
        if (cmd%count('TRI') == 0) return
        occ = cmd%occurrence('TRI', 1)
        call occ%get_texts('NOM_PARA', names, st)
        if (st%ok()) call occ%get_text('ORDRE', order_text, st)
        if (st%failed()) return
        allocate (keys(size(names)))
        do k = 1, size(names)
            call require(t, names(k)%s, keys(k), st)
            if (st%failed()) then
                call relocate_at(occ, 'NOM_PARA', st)
                return
            end if
        end do
        call table_sorted_rows(t, keys, order_text == 'DECROISSANT', order)
        if (allocated(t%name)) name = t%name
        t = table_select_rows(t, order)
        if (allocated(name)) t%name = name
    end subroutine sort_by_tri

    subroutine require(t, name, column, st)
        use table_concept, only: table_require_column
        type(table_t), intent(in) :: t
        character(len=*), intent(in) :: name
        integer, intent(out) :: column
        type(status_t), intent(inout) :: st
        call table_require_column(t, name, column, st)
    end subroutine require

    !> The columns to print: NOM_PARA (those the table has, a warning for the others) or
    !> all; without those that hold no value in any row.
    subroutine printed_columns(ctx, cmd, t, columns)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(table_t), intent(in) :: t
        integer, allocatable, intent(out) :: columns(:)
        type(string_t), allocatable :: names(:)
        type(status_t) :: st
        integer :: k, c
        allocate (columns(0))
        if (cmd%has('NOM_PARA')) then
            call cmd%get_texts('NOM_PARA', names, st)
            do k = 1, size(names)
                c = table_find_column(t, names(k)%s)
                if (c == 0) then
                    call warn_at(ctx, cmd, 'NOM_PARA', 'table ' // concept_display_name(t) // &
                        ' has no column ' // names(k)%s // ': it is not printed')
                    cycle
                end if
                if (any(columns == c)) cycle
                columns = [columns, c]
            end do
        else
            columns = [(c, c=1, t%n_columns)]
        end if
        columns = pack(columns, [(any(t%columns(columns(k))%present(1:t%n_rows)), &
                                  k=1, size(columns))])
    end subroutine printed_columns

    !> PAGINATION: a table per combination of the distinct values of the paging columns
    !> (each in increasing order), without those columns, its title saying the values.
    subroutine paged_lines(cmd, t, columns, pages, title, layout, lines, st)
        type(command_t), intent(in) :: cmd
        type(table_t), intent(in) :: t
        integer, intent(in) :: columns(:)
        type(string_t), intent(in) :: pages(:), title(:)
        type(table_layout_t), intent(in) :: layout
        type(string_t), allocatable, intent(out) :: lines(:)
        type(status_t), intent(inout) :: st
        integer, allocatable :: keys(:), order(:), starts(:), kept(:), rows(:)
        type(string_t), allocatable :: page_title(:), page(:)
        integer :: k, g, c, i
        allocate (lines(0), keys(0))
        do k = 1, size(pages)
            c = table_find_column(t, pages(k)%s)
            if (c == 0) then
                call require(t, pages(k)%s, c, st)
                call relocate_at(cmd, 'PAGINATION', st)
                return
            end if
            if (.not. any(columns == c)) cycle     ! Code_Aster: only printed columns page
            keys = [keys, c]
        end do
        kept = pack(columns, [(.not. any(keys == columns(i)), i=1, size(columns))])
        if (size(keys) == 0) then
            call table_text_lines(t, columns, all_rows(t), title, layout, lines)
            return
        end if
        call table_sorted_rows(t, keys, .false., order)
        ! groups of rows with equal keys (rows without a value in a key column are left out,
        ! as Code_Aster pages only on the values present)
        allocate (starts(0))
        do i = 1, size(order)
            if (.not. keys_present(t, keys, order(i))) cycle
            if (size(starts) > 0) then
                if (compare_table_rows(t, keys, order(starts(size(starts))), order(i)) == 0) &
                    cycle
            end if
            starts = [starts, i]
        end do
        do g = 1, size(starts)
            rows = [integer ::]
            do i = starts(g), size(order)
                if (.not. keys_present(t, keys, order(i))) cycle
                if (compare_table_rows(t, keys, order(starts(g)), order(i)) /= 0) exit
                rows = [rows, order(i)]
            end do
            call sort_ints(rows)
            page_title = title
            do k = 1, size(keys)
                call append_string(page_title, t%columns(keys(k))%name // ': ' // &
                                   cell_text(t, keys(k), rows(1)))
            end do
            call table_text_lines(t, kept, rows, page_title, layout, page)
            lines = [lines, page]
        end do
    end subroutine paged_lines

    !> True when row `row` has a value in every column of `keys`.
    pure logical function keys_present(t, keys, row)
        type(table_t), intent(in) :: t
        integer, intent(in) :: keys(:), row
        integer :: k
        keys_present = .true.
        do k = 1, size(keys)
            if (.not. t%columns(keys(k))%present(row)) keys_present = .false.
        end do
    end function keys_present

    !> A cell as Python's str() writes it (for titles and crossed column names).
    function cell_text(t, column, row) result(text)
        type(table_t), intent(in) :: t
        integer, intent(in) :: column, row
        character(len=:), allocatable :: text
        select case (t%columns(column)%kind)
        case (TABLE_TEXT)
            text = table_cell_text(t, column, row)
        case (TABLE_INT)
            text = to_text(t%columns(column)%ints(row))
        case default
            text = float_repr(table_cell_real(t, column, row))
        end select
    end function cell_text

    !> Insertion sort of a short list of row indices (the rows of one page keep their
    !> order in the table).
    pure subroutine sort_ints(a)
        integer, intent(inout) :: a(:)
        integer :: i, j, v
        do i = 2, size(a)
            v = a(i)
            j = i - 1
            do while (j >= 1)
                if (a(j) <= v) exit
                a(j + 1) = a(j)
                j = j - 1
            end do
            a(j + 1) = v
        end do
    end subroutine sort_ints

    !> TABLEAU_CROISE: a table (P1, P2, P3) printed as P3 against P2 (rows) and P1
    !> (columns): the first column, named 'P2/P1', holds the distinct values of P2, the
    !> others are named after the distinct values of P1 (Code_Aster's Table.Croise).
    subroutine crossed_lines(cmd, t, columns, title, layout, lines, st)
        type(command_t), intent(in) :: cmd
        type(table_t), intent(in) :: t
        integer, intent(in) :: columns(:)
        type(string_t), intent(in) :: title(:)
        type(table_layout_t), intent(in) :: layout
        type(string_t), allocatable, intent(out) :: lines(:)
        type(status_t), intent(inout) :: st
        type(table_t) :: crossed
        type(string_t), allocatable :: crossed_title(:)
        integer, allocatable :: ys(:), xs(:)
        integer :: py, px, pz, c, i, j, row
        allocate (lines(0))
        if (size(columns) /= 3) then
            call cmd%error_at('FORMAT', 'FORMAT=''TABLEAU_CROISE'' crosses a table of ' // &
                'three columns (P1, P2, P3: P3 against P2 and P1); this one prints ' // &
                to_text(int(size(columns), i4)) // ' (choose them with NOM_PARA)', st, &
                STATUS_MODEL_ERROR)
            return
        end if
        py = columns(1); px = columns(2); pz = columns(3)
        call distinct_rows(t, py, ys)
        call distinct_rows(t, px, xs)
        call table_init(crossed)
        crossed%name = t%name
        call table_add_column(crossed, t%columns(px)%name // '/' // t%columns(py)%name, &
            t%columns(px)%kind, c, st, t%columns(px)%width)
        do j = 1, size(ys)
            if (st%failed()) return
            call table_add_column(crossed, cell_text(t, py, ys(j)), t%columns(pz)%kind, c, st, &
                                  t%columns(pz)%width)
        end do
        if (st%failed()) then
            call relocate_at(cmd, 'FORMAT', st)
            return
        end if
        call table_add_rows(crossed, size(xs))
        do i = 1, size(xs)
            call table_copy_cell(t, px, xs(i), crossed, 1, i, st)
            do row = 1, t%n_rows
                if (.not. (t%columns(px)%present(row) .and. t%columns(py)%present(row))) cycle
                if (compare_table_rows(t, [px], row, xs(i)) /= 0) cycle
                do j = 1, size(ys)
                    if (compare_table_rows(t, [py], row, ys(j)) /= 0) cycle
                    call table_copy_cell(t, pz, row, crossed, j + 1, i, st)
                end do
            end do
        end do
        if (st%failed()) return
        crossed_title = title
        call append_string(crossed_title, t%columns(pz)%name // ' FONCTION DE ' // &
                           t%columns(px)%name // ' ET ' // t%columns(py)%name)
        call table_text_lines(crossed, [(c, c=1, crossed%n_columns)], all_rows(crossed), &
                              crossed_title, layout, lines)
    end subroutine crossed_lines

    !> One row per distinct present value of `column`, in increasing order of the values.
    subroutine distinct_rows(t, column, rows)
        type(table_t), intent(in) :: t
        integer, intent(in) :: column
        integer, allocatable, intent(out) :: rows(:)
        integer, allocatable :: order(:)
        integer :: i
        call table_sorted_rows(t, [column], .false., order)
        allocate (rows(0))
        do i = 1, size(order)
            if (.not. t%columns(column)%present(order(i))) cycle
            if (size(rows) > 0) then
                if (compare_table_rows(t, [column], rows(size(rows)), order(i)) == 0) cycle
            end if
            rows = [rows, order(i)]
        end do
    end subroutine distinct_rows

end module impr_table_command
