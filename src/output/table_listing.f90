!> The text of a table as Code_Aster writes it (IMPR_TABLE, U4.91.03; Table.ReprTable of
!> code_aster/Objects/table_py.py), so that scripts reading Code_Aster's tables read
!> parasol's:
!>
!>   FORMAT='TABLEAU' (default)          FORMAT='ASTER'
!>   #                                   #
!>   #-----... (80 dashes)               #-----...
!>   #                                   #
!>   #<title line>                       #DEBUT_TABLE
!>   NOEUD    DX           DY            #TITRE <title line>
!>   N1        1.00000E+00 -2.50000E-01   NOEUD    DX           DY
!>   N2       -            3.00000E+00    K8       R            R
!>   (an empty line)                      N1        1.00000E+00 -2.50000E-01
!>                                       ...
!>                                       #FIN_TABLE
!> Each column is as wide as the widest of its name and its formats: reals in FORMAT_R
!> (Fortran E12.5 by default, Python's %12.5E: one digit before the point), integers in
!> %12d, texts of a Kn column left-aligned in n; a column wider than its format aligns
!> its values right. An absent cell is '-' (AGRAF: '\-'); a row with no value at all is
!> not written. With a SEPARATEUR other than blanks the column names are not padded.
!> DEBUT_TABLE replaces the three heading lines, FIN_TABLE the final empty line;
!> DEBUT_LIGNE / FIN_LIGNE frame every other line; COMM_PARA starts the line of names.
module table_listing
    use strings, only: string_t
    use table_concept, only: table_t, table_column_t, TABLE_INT, TABLE_REAL, TABLE_TEXT, &
        table_kind_label
    use python_format, only: real_format_t, format_real_column
    implicit none
    private

    !> Code_Aster's integer format (%12d).
    integer, parameter :: INT_WIDTH = 12
    !> Dashes of the default heading.
    integer, parameter :: HEADING_DASHES = 80

    !> Text being built, with spare capacity.
    type :: text_buffer_t
        character(len=:), allocatable :: data
        integer :: used = 0
    end type text_buffer_t

    !> The formatted values of one numeric column, per row written.
    type :: cell_texts_t
        character(len=:), allocatable :: text(:)
        integer, allocatable :: length(:)
    end type cell_texts_t

    !> How IMPR_TABLE lays a table out.
    type, public :: table_layout_t
        character(len=:), allocatable :: format          !< TABLEAU, ASTER or AGRAF
        type(real_format_t) :: real_format
        logical :: has_heading = .false.
        character(len=:), allocatable :: heading          !< DEBUT_TABLE
        character(len=:), allocatable :: footer           !< FIN_TABLE
        character(len=:), allocatable :: separator        !< SEPARATEUR
        character(len=:), allocatable :: comment          !< COMMENTAIRE
        character(len=:), allocatable :: names_prefix     !< COMM_PARA
        character(len=:), allocatable :: line_start       !< DEBUT_LIGNE
        character(len=:), allocatable :: line_end         !< FIN_LIGNE (default: new line)
    end type table_layout_t

    public :: default_table_layout, table_text_lines

contains

    !> The layout of FORMAT='TABLEAU' with every default of IMPR_TABLE.
    function default_table_layout() result(layout)
        type(table_layout_t) :: layout
        layout%format = 'TABLEAU'
        layout%footer = ''
        layout%separator = ' '
        layout%comment = '#'
        layout%names_prefix = ''
        layout%line_start = ''
        layout%line_end = new_line('a')
        layout%heading = ''
    end function default_table_layout

    !> The lines of table `t`, columns `columns` (indices, in that order), rows `rows`.
    !>  title : in, the title lines to write (table title, TITRE, filters)
    !>  lines : out, the lines of the text, built as Code_Aster joins it (DEBUT_LIGNE, the
    !>          line, FIN_LIGNE: a FIN_LIGNE without a new line joins lines)
    subroutine table_text_lines(t, columns, rows, title, layout, lines)
        type(table_t), intent(in) :: t
        integer, intent(in) :: columns(:), rows(:)
        type(string_t), intent(in) :: title(:)
        type(table_layout_t), intent(in) :: layout
        type(string_t), allocatable, intent(out) :: lines(:)
        integer, allocatable :: widths(:)
        type(string_t), allocatable :: names(:), types(:)
        type(cell_texts_t), allocatable :: numbers(:)
        logical :: aster, padded_names
        integer :: c, k, n
        type(text_buffer_t) :: buffer
        aster = layout%format == 'ASTER'
        padded_names = index(layout%separator, ' ') > 0
        n = size(columns)
        allocate (widths(n), names(n), types(n))
        do c = 1, n
            associate (col => t%columns(columns(c)))
                widths(c) = column_width(col, layout%real_format)
                names(c)%s = header_cell(col, col%name, widths(c), layout%real_format)
                if (.not. padded_names) names(c)%s = trim(adjustl(names(c)%s))
                types(c)%s = header_cell(col, table_kind_label(col), widths(c), &
                                         layout%real_format)
            end associate
        end do
        buffer%used = 0
        allocate (character(len=4096) :: buffer%data)
        if (layout%has_heading) then
            call add_raw(layout%heading // new_line('a'))
        else
            call add_raw(layout%comment // new_line('a') // layout%comment // &
                         repeat('-', HEADING_DASHES) // new_line('a') // layout%comment // &
                         new_line('a'))
        end if
        if (aster) call add('#DEBUT_TABLE')
        do k = 1, size(title)
            if (aster) then
                call add('#TITRE ' // title(k)%s)
            else
                call add(layout%comment // title(k)%s)
            end if
        end do
        call add(layout%names_prefix // joined(names, aster))
        if (aster) call add(joined(types, .true.))
        call prepare_cells()
        do k = 1, size(rows)
            if (.not. any([(t%columns(columns(c))%present(rows(k)), c=1, n)])) cycle
            call add_raw(layout%line_start)
            do c = 1, n
                if (c > 1 .or. aster) call add_raw(layout%separator)
                call add_cell(c, k)
            end do
            call add_raw(layout%line_end)
        end do
        if (aster) call add('#FIN_TABLE')
        call add_raw(layout%footer // new_line('a'))
        call split_lines(buffer%data(1:buffer%used), lines)
    contains
        !> The formatted numbers of each numeric column, for the rows written, in one
        !> internal write per column (format_real_column).
        subroutine prepare_cells()
            integer :: cc, i
            character(len=24), allocatable :: digits(:)
            allocate (numbers(n))
            do cc = 1, n
                associate (col => t%columns(columns(cc)), cell => numbers(cc))
                    select case (col%kind)
                    case (TABLE_REAL)
                        allocate (character(len=max(64, layout%real_format%lead + &
                                  layout%real_format%width + 1)) :: cell%text(size(rows)))
                        allocate (cell%length(size(rows)))
                        call format_real_column(layout%real_format, col%reals(rows), cell%text, &
                                                cell%length)
                    case (TABLE_INT)
                        allocate (digits(size(rows)))
                        allocate (character(len=24) :: cell%text(size(rows)))
                        allocate (cell%length(size(rows)))
                        if (size(rows) > 0) write (digits, '(i0)') col%ints(rows)
                        do i = 1, size(rows)
                            cell%length(i) = max(len_trim(digits(i)), INT_WIDTH)
                            cell%text(i) = repeat(' ', cell%length(i) - len_trim(digits(i))) // &
                                trim(digits(i))
                        end do
                        deallocate (digits)
                    case default
                    end select
                end associate
            end do
        end subroutine prepare_cells

        !> Cell (column c, k-th row written) into the buffer, as value_cell makes it.
        subroutine add_cell(c, k)
            integer, intent(in) :: c, k
            integer :: own, lead, row
            row = rows(k)
            associate (col => t%columns(columns(c)))
                lead = 0
                select case (col%kind)
                case (TABLE_TEXT)
                    own = col%width
                case (TABLE_INT)
                    own = INT_WIDTH
                case default
                    lead = layout%real_format%lead
                    own = lead + layout%real_format%width
                end select
                if (.not. col%present(row) .and. layout%format == 'AGRAF') call add_raw('\')
                call add_spaces(max(widths(c) - own, 0))
                if (.not. col%present(row)) then
                    call add_spaces(lead)
                    call add_raw('-')
                    call add_spaces(own - lead - 1)
                    return
                end if
                select case (col%kind)
                case (TABLE_TEXT)
                    call add_raw(col%texts(row)%s)
                    call add_spaces(col%width - len(col%texts(row)%s))
                case default
                    call add_raw(numbers(c)%text(k)(1:numbers(c)%length(k)))
                end select
            end associate
        end subroutine add_cell

        subroutine add_spaces(count)
            integer, intent(in) :: count
            if (count <= 0) return
            call reserve(count)
            buffer%data(buffer%used + 1:buffer%used + count) = repeat(' ', count)
            buffer%used = buffer%used + count
        end subroutine add_spaces

        subroutine reserve(extra)
            integer, intent(in) :: extra
            character(len=:), allocatable :: bigger
            if (buffer%used + extra > len(buffer%data)) then
                allocate (character(len=max(2 * len(buffer%data), buffer%used + extra)) :: &
                          bigger)
                bigger(1:buffer%used) = buffer%data(1:buffer%used)
                call move_alloc(bigger, buffer%data)
            end if
        end subroutine reserve

        !> A line framed by DEBUT_LIGNE and FIN_LIGNE.
        subroutine add(text)
            character(len=*), intent(in) :: text
            call add_raw(layout%line_start // text // layout%line_end)
        end subroutine add

        !> Appends to the buffer (its capacity doubles: linear in the table's size).
        subroutine add_raw(text)
            character(len=*), intent(in) :: text
            call reserve(len(text))
            buffer%data(buffer%used + 1:buffer%used + len(text)) = text
            buffer%used = buffer%used + len(text)
        end subroutine add_raw

        !> The cells joined by the separator; ASTER starts with a separator.
        function joined(parts, leading) result(text)
            type(string_t), intent(in) :: parts(:)
            logical, intent(in) :: leading
            character(len=:), allocatable :: text
            integer :: i
            text = ''
            do i = 1, size(parts)
                if (i > 1 .or. leading) text = text // layout%separator
                text = text // parts(i)%s
            end do
        end function joined
    end subroutine table_text_lines

    !> Width of a column: the widest of its name and of its formats (Code_Aster's FMT:
    !> for numbers the real and integer formats, for Kn columns n).
    pure integer function column_width(col, real_format) result(w)
        type(table_column_t), intent(in) :: col
        type(real_format_t), intent(in) :: real_format
        if (col%kind == TABLE_TEXT) then
            w = max(len(col%name), col%width)
        else
            w = max(len(col%name), real_format%lead + real_format%width, INT_WIDTH)
        end if
    end function column_width

    !> A column's name (or type) in its column: left-aligned in the width of the column's
    !> own text format, shifted right when the column is wider than that format.
    pure function header_cell(col, label, width, real_format) result(text)
        type(table_column_t), intent(in) :: col
        character(len=*), intent(in) :: label
        integer, intent(in) :: width
        type(real_format_t), intent(in) :: real_format
        character(len=:), allocatable :: text
        integer :: own, lead, shift
        lead = 0
        select case (col%kind)
        case (TABLE_TEXT)
            own = col%width
        case (TABLE_INT)
            own = INT_WIDTH
        case default
            lead = real_format%lead
            own = real_format%lead + real_format%width
        end select
        shift = max(min(width - len(label), width - own), 0)
        text = repeat(' ', shift + lead) // pad_right(label, own - lead)
    end function header_cell

    !> The lines of a text (split at new lines; a final new line ends the last line).
    subroutine split_lines(text, lines)
        character(len=*), intent(in) :: text
        type(string_t), allocatable, intent(out) :: lines(:)
        integer :: n, k, start, i
        n = 0
        do k = 1, len(text)
            if (text(k:k) == new_line('a')) n = n + 1
        end do
        if (len(text) > 0) then
            if (text(len(text):len(text)) /= new_line('a')) n = n + 1
        end if
        allocate (lines(n))
        start = 1
        i = 0
        do k = 1, len(text)
            if (text(k:k) /= new_line('a')) cycle
            i = i + 1
            lines(i)%s = text(start:k - 1)
            start = k + 1
        end do
        if (i < n) lines(n)%s = text(start:)
    end subroutine split_lines

    !> `text` padded with blanks to `width` (never cut).
    pure function pad_right(text, width) result(out)
        character(len=*), intent(in) :: text
        integer, intent(in) :: width
        character(len=:), allocatable :: out
        out = text // repeat(' ', max(width - len(text), 0))
    end function pad_right

end module table_listing
