!> IMPR_RESU(FORMAT='RESULTAT') tables of any field (doc/listings.md, "IMPR_RESU tables"):
!> a header naming the result (or the CHAM_GD), the field, NUME_ORDRE and INST, a column
!> header, then one row per
!>  NOEU       node: NOEUD [COOR_X COOR_Y (COOR_Z)] components;
!>  ELGA       cell, point and sub-point: MAILLE POINT [SOUS_POINT] components;
!>  ELNO       cell, node and sub-point: MAILLE NOEUD [SOUS_POINT] [COOR_*] components;
!>  ELEM/CART  cell: MAILLE components;
!> values in E format with 13 significant digits (real_e13), `-` for a component a node or
!> cell does not carry (columns stay aligned token by token for parasol-diff); a row with
!> none of the printed components, or (BORNE_INF / BORNE_SUP) none within the bounds, is
!> left out. SOUS_POINT is a column when some printed cell has more than one. VALE_MAX /
!> VALE_MIN add, per component, its largest / smallest value and where it is.
module field_listing
    use kinds, only: dp, i4, i8
    use strings, only: string_t, real_e13, to_text
    use mesh_types, only: mesh_t, node_name, cell_name
    use field_types, only: field_t, field_type_cham, FIELD_NOEU, FIELD_ELGA, FIELD_ELNO
    use impr_resu_select, only: print_set_t, print_item_t
    use field_viewer_data, only: field_columns
    implicit none
    private

    !> Width of a value column: a 13-digit E value with a 3-digit exponent is 20 characters.
    integer, parameter :: VALUE_WIDTH = 22
    !> Smallest width of a name column (Code_Aster names have up to 8 characters).
    integer, parameter :: NAME_WIDTH = 8
    !> Printed for a component a node or cell does not carry.
    character(len=*), parameter, public :: FIELD_LISTING_ABSENT = '-'

    !> Where an extreme value is.
    type :: extreme_t
        logical :: found = .false.
        real(dp) :: value = 0.0_dp
        character(len=:), allocatable :: place
    end type extreme_t

    public :: field_table_lines

contains

    !> The lines of the table of `item` (module header), ending with an empty line.
    subroutine field_table_lines(set, item, lines)
        type(print_set_t), intent(in) :: set
        type(print_item_t), intent(in) :: item
        type(string_t), allocatable, intent(out) :: lines(:)
        integer(i4), allocatable :: cols(:)
        type(string_t), allocatable :: names(:)
        type(extreme_t), allocatable :: highest(:), lowest(:)
        integer :: n
        call printed_columns(set, item%f, cols, names)
        allocate (highest(size(cols)), lowest(size(cols)))
        allocate (lines(16))
        n = 0
        call add(lines, n, header(set, item))
        if (len(set%subtitle) > 0) call add(lines, n, ' ' // set%subtitle)
        if (item%f%location == FIELD_NOEU) then
            call node_rows(set, item%f, cols, names, lines, n, highest, lowest)
        else
            call cell_rows(set, item%f, cols, names, lines, n, highest, lowest)
        end if
        if (set%vale_max) call extreme_lines('VALE_MAX', names, highest, lines, n)
        if (set%vale_min) call extreme_lines('VALE_MIN', names, lowest, lines, n)
        call add(lines, n, '')
        lines = lines(1:n)
    end subroutine field_table_lines

    ! ' ---- RESULTAT resu  NOM_CHAM DEPL  NUME_ORDRE 1  INST 1.0E+00' or, for a CHAM_GD,
    ! ' ---- CHAM_GD CH  NOEU_DEPL_R'.
    function header(set, item) result(text)
        type(print_set_t), intent(in) :: set
        type(print_item_t), intent(in) :: item
        character(len=:), allocatable :: text
        if (item%has_instant) then
            text = ' ---- RESULTAT ' // set%owner // '  NOM_CHAM ' // item%name // &
                '  NUME_ORDRE ' // to_text(item%nume_ordre) // '  INST ' // real_e13(item%inst)
        else
            text = ' ---- CHAM_GD ' // item%name // '  ' // field_type_cham(item%f)
        end if
    end function header

    ! The field's columns printed (field_viewer_data field_columns) and their names.
    subroutine printed_columns(set, f, cols, names)
        type(print_set_t), intent(in) :: set
        type(field_t), intent(in) :: f
        integer(i4), allocatable, intent(out) :: cols(:)
        type(string_t), allocatable, intent(out) :: names(:)
        integer(i4) :: k
        cols = field_columns(f, set%components, set%cell_taken)
        allocate (names(size(cols)))
        do k = 1, size(cols, kind=i4)
            names(k)%s = f%components(cols(k))%s
        end do
    end subroutine printed_columns

    ! NOEU: a row per printed node carrying some printed component.
    subroutine node_rows(set, f, cols, names, lines, n, highest, lowest)
        type(print_set_t), intent(in) :: set
        type(field_t), intent(in) :: f
        integer(i4), intent(in) :: cols(:)
        type(string_t), intent(in) :: names(:)
        type(string_t), allocatable, intent(inout) :: lines(:)
        integer, intent(inout) :: n
        type(extreme_t), intent(inout) :: highest(:), lowest(:)
        character(len=:), allocatable :: row
        real(dp) :: v(size(cols))
        logical :: has(size(cols))
        integer(i4) :: k, node, j, width, dims
        width = NAME_WIDTH
        do k = 1, size(set%nodes, kind=i4)
            width = max(width, len(node_name(set%mesh, set%nodes(k))))
        end do
        dims = merge(3, 2, set%mesh%dim == 3)
        row = ' ' // pad('NOEUD', width + 1)
        if (set%coordinates) row = row // pad('COOR_X', VALUE_WIDTH) // &
            pad('COOR_Y', VALUE_WIDTH)
        if (set%coordinates .and. dims == 3) row = row // pad('COOR_Z', VALUE_WIDTH)
        do j = 1, size(names)
            row = row // pad(names(j)%s, VALUE_WIDTH)
        end do
        call add(lines, n, trim(row))
        do k = 1, size(set%nodes, kind=i4)
            node = set%nodes(k)
            if (node > f%n_nodes) cycle
            do j = 1, size(cols)
                has(j) = f%node_has(cols(j), node)
                v(j) = f%node_values(cols(j), node)
            end do
            if (.not. shown(set, has, v)) cycle
            row = ' ' // pad(node_name(set%mesh, node), width + 1)
            if (set%coordinates) then
                do j = 1, dims
                    row = row // pad(real_e13(set%mesh%coords(j, node)), VALUE_WIDTH)
                end do
            end if
            call append_values(row, has, v)
            call add(lines, n, trim(row))
            call note_extremes(has, v, 'NOEUD ' // node_name(set%mesh, node), highest, lowest)
        end do
    end subroutine node_rows

    ! ELGA / ELNO / ELEM / CART: a row per printed cell, point and sub-point.
    subroutine cell_rows(set, f, cols, names, lines, n, highest, lowest)
        type(print_set_t), intent(in) :: set
        type(field_t), intent(in) :: f
        integer(i4), intent(in) :: cols(:)
        type(string_t), intent(in) :: names(:)
        type(string_t), allocatable, intent(inout) :: lines(:)
        integer, intent(inout) :: n
        type(extreme_t), intent(inout) :: highest(:), lowest(:)
        character(len=:), allocatable :: row, place
        real(dp) :: v(size(cols))
        logical :: has(size(cols))
        integer(i4) :: slot(size(cols))
        integer(i4) :: c, p, s, j, q, width, node, dims
        integer(i8) :: base
        logical :: sub_column, per_point, at_nodes, coords
        width = NAME_WIDTH
        sub_column = .false.
        do c = 1, f%n_cells
            if (.not. printed_cell(set, f, c)) cycle
            if (.not. any([(any(f%sets(f%cell_set(c))%cmp == cols(j)), j = 1, &
                size(cols, kind=i4))])) cycle
            width = max(width, len(cell_name(set%mesh, c)))
            if (f%n_subpoints(c) > 1) sub_column = .true.
        end do
        at_nodes = f%location == FIELD_ELNO
        per_point = f%location == FIELD_ELGA .or. at_nodes
        coords = set%coordinates .and. at_nodes
        dims = merge(3, 2, set%mesh%dim == 3)
        row = ' ' // pad('MAILLE', width + 1)
        if (f%location == FIELD_ELGA) row = row // pad('POINT', NAME_WIDTH)
        if (at_nodes) row = row // pad('NOEUD', width + 1)
        if (sub_column) row = row // pad('SOUS_POINT', 12)
        if (coords) row = row // pad('COOR_X', VALUE_WIDTH) // pad('COOR_Y', VALUE_WIDTH)
        if (coords .and. dims == 3) row = row // pad('COOR_Z', VALUE_WIDTH)
        do j = 1, size(names)
            row = row // pad(names(j)%s, VALUE_WIDTH)
        end do
        call add(lines, n, trim(row))
        do c = 1, f%n_cells
            if (.not. printed_cell(set, f, c)) cycle
            associate (cmp => f%sets(f%cell_set(c))%cmp)
                do j = 1, size(cols)
                    slot(j) = 0
                    do q = 1, size(cmp, kind=i4)
                        if (cmp(q) == cols(j)) slot(j) = q
                    end do
                end do
                if (all(slot == 0)) cycle
                do p = 1, f%n_points(c)
                    node = 0
                    if (at_nodes) then
                        node = set%mesh%cell_nodes(set%mesh%cell_ptr(c) + p - 1)
                        if (.not. set%node_taken(node)) cycle
                    end if
                    do s = 1, f%n_subpoints(c)
                        base = f%offset(c) + (int(p - 1, i8) * f%n_subpoints(c) + (s - 1)) * &
                            size(cmp)
                        do j = 1, size(cols)
                            has(j) = slot(j) > 0
                            v(j) = 0.0_dp
                            if (has(j)) v(j) = f%values(base + slot(j))
                        end do
                        if (.not. shown(set, has, v)) cycle
                        row = ' ' // pad(cell_name(set%mesh, c), width + 1)
                        place = 'MAILLE ' // cell_name(set%mesh, c)
                        if (f%location == FIELD_ELGA) then
                            row = row // pad(to_text(p), NAME_WIDTH)
                            place = place // ' POINT ' // to_text(p)
                        end if
                        if (at_nodes) then
                            row = row // pad(node_name(set%mesh, node), width + 1)
                            place = place // ' NOEUD ' // node_name(set%mesh, node)
                        end if
                        if (sub_column) then
                            row = row // pad(to_text(s), 12)
                            place = place // ' SOUS_POINT ' // to_text(s)
                        end if
                        if (coords) then
                            do j = 1, dims
                                row = row // pad(real_e13(set%mesh%coords(j, node)), &
                                    VALUE_WIDTH)
                            end do
                        end if
                        call append_values(row, has, v)
                        call add(lines, n, trim(row))
                        call note_extremes(has, v, place, highest, lowest)
                    end do
                    if (.not. per_point) exit
                end do
            end associate
        end do
    end subroutine cell_rows

    ! A cell of the field that the occurrence prints.
    pure logical function printed_cell(set, f, c)
        type(print_set_t), intent(in) :: set
        type(field_t), intent(in) :: f
        integer(i4), intent(in) :: c
        printed_cell = f%n_points(c) > 0
        if (printed_cell .and. c <= size(set%cell_taken)) printed_cell = set%cell_taken(c)
    end function printed_cell

    ! A row is shown when it carries a printed component within BORNE_INF / BORNE_SUP.
    pure logical function shown(set, has, v)
        type(print_set_t), intent(in) :: set
        logical, intent(in) :: has(:)
        real(dp), intent(in) :: v(:)
        logical :: inside(size(v))
        inside = has
        if (set%has_lower) inside = inside .and. v >= set%lower
        if (set%has_upper) inside = inside .and. v <= set%upper
        shown = any(inside)
    end function shown

    subroutine append_values(row, has, v)
        character(len=:), allocatable, intent(inout) :: row
        logical, intent(in) :: has(:)
        real(dp), intent(in) :: v(:)
        integer :: j
        do j = 1, size(v)
            if (has(j)) then
                row = row // pad(real_e13(v(j)), VALUE_WIDTH)
            else
                row = row // pad(FIELD_LISTING_ABSENT, VALUE_WIDTH)
            end if
        end do
    end subroutine append_values

    subroutine note_extremes(has, v, place, highest, lowest)
        logical, intent(in) :: has(:)
        real(dp), intent(in) :: v(:)
        character(len=*), intent(in) :: place
        type(extreme_t), intent(inout) :: highest(:), lowest(:)
        integer :: j
        do j = 1, size(v)
            if (.not. has(j)) cycle
            if (.not. highest(j)%found .or. v(j) > highest(j)%value) then
                highest(j) = extreme_t(.true., v(j), place)
            end if
            if (.not. lowest(j)%found .or. v(j) < lowest(j)%value) then
                lowest(j) = extreme_t(.true., v(j), place)
            end if
        end do
    end subroutine note_extremes

    ! ' VALE_MAX  SIXX  3.0E+01  NOEUD N5' per component.
    subroutine extreme_lines(what, names, extremes, lines, n)
        character(len=*), intent(in) :: what
        type(string_t), intent(in) :: names(:)
        type(extreme_t), intent(in) :: extremes(:)
        type(string_t), allocatable, intent(inout) :: lines(:)
        integer, intent(inout) :: n
        integer :: j
        do j = 1, size(names)
            if (.not. extremes(j)%found) cycle
            call add(lines, n, ' ' // pad(what, 10) // pad(names(j)%s, 10) // &
                pad(real_e13(extremes(j)%value), VALUE_WIDTH) // extremes(j)%place)
        end do
    end subroutine extreme_lines

    ! Appends a line, growing the array by doubling.
    subroutine add(lines, n, text)
        type(string_t), allocatable, intent(inout) :: lines(:)
        integer, intent(inout) :: n
        character(len=*), intent(in) :: text
        type(string_t), allocatable :: bigger(:)
        integer :: k
        if (n == size(lines)) then
            allocate (bigger(2 * size(lines)))
            do k = 1, n
                call move_alloc(lines(k)%s, bigger(k)%s)
            end do
            call move_alloc(bigger, lines)
        end if
        n = n + 1
        lines(n)%s = text
    end subroutine add

    !> `text` left-aligned in `width` columns, or followed by one blank when longer.
    pure function pad(text, width) result(out)
        character(len=*), intent(in) :: text
        integer, intent(in) :: width
        character(len=:), allocatable :: out
        out = text // repeat(' ', max(1, width - len(text)))
    end function pad

end module field_listing
