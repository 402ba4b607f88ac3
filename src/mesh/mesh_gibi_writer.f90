!> The .mail text of a GIBI file read by mesh_gibi_reader, as Code_Aster's PRE_GIBI writes
!> it (giecas, giecma; the names and orders are described in mesh_gibi_reader's header).
module mesh_gibi_writer
    use kinds, only: i4, i8
    use strings, only: string_t, to_text
    use stable_sort, only: item_order_t, stable_order
    use mesh_gibi_data, only: gibi_t, ASTER_NAMES, PERM, per_line, objects_written, &
        is_internal
    implicit none
    private

    public :: write_aster, join_lines

    !> The cells of pile 1 as stable_order sorts them (identical_cells).
    type, extends(item_order_t) :: cell_order_t
        type(gibi_t), pointer :: g => null()
        integer(i4), allocatable :: start(:)   !< where a cell's points start in its object
        integer(i4), allocatable :: owner(:)   !< its object
    contains
        procedure :: compare => compare_cells
    end type cell_order_t

contains

    ! The .mail text (giecas, giecma).
    subroutine write_aster(g, text, notes, origin)
        type(gibi_t), intent(in), target :: g
        character(len=:), allocatable, intent(out) :: text
        type(string_t), allocatable, intent(inout) :: notes(:)
        integer(i4), allocatable, intent(out) :: origin(:)
        type(string_t), allocatable :: out(:)
        integer(i4), allocatable :: first_cell(:), same_as(:), rep(:), nodes(:), mark(:), &
            members(:), name_ptr(:), name_list(:)
        logical, allocatable :: written(:), done(:), used(:)
        integer(i4) :: n_out, i, j, k, c, n_cells, cell, cls, n_left, n_merged, t, here
        character(len=:), allocatable :: line
        character(len=24) :: number
        allocate (out(1024), origin(1024))
        n_out = 0
        here = 1
        call put(' TITRE')
        call put(' %  GIBI FECIT')
        call put(' FINSF')
        call put(' %')
        ! nodes: those some point uses, in increasing order
        allocate (used(size(g%coords, 2)), source=.false.)
        used(g%indirection) = .true.
        call put(merge(' COOR_3D', ' COOR_2D', g%dim == 3))
        do j = 1, size(used, kind=i4)
            if (.not. used(j)) cycle
            here = g%coords_line + int((int(j - 1, i8) * (g%dim + 1)) / 3, i4)
            line = ' ' // pad8('N' // to_text(j))
            do k = 1, g%dim
                write (number, '(1x, es22.14e3)') g%coords(k, j)
                line = line // trim(number)
            end do
            call put(line)
        end do
        call put(' FINSF')
        call put(' %')
        if (count(.not. used) > 0) notes = [notes, string_t('GIBI: ' // &
            to_text(count(.not. used)) // ' node(s) no point uses left out of the mesh ' // &
            '(PREPOST5_19)')]
        ! cells: the first of each set of cells with the same nodes (gidoma)
        allocate (first_cell(size(g%objects) + 1))
        first_cell(1) = 0
        do i = 1, size(g%objects, kind=i4)
            first_cell(i + 1) = first_cell(i) + g%objects(i)%n_cells
        end do
        n_cells = first_cell(size(first_cell))
        same_as = identical_cells(g, first_cell, n_cells)
        ! giecma: a cell goes out under its own number unless one with the same nodes went
        ! out before; the set then takes the number of the first written
        allocate (done(n_cells), source=.false.)
        rep = [(c, c = 1, n_cells)]
        allocate (mark(n_cells), source=0)
        allocate (members(n_cells))
        written = objects_written(g)
        n_left = 0
        n_merged = 0
        do i = 1, size(g%objects, kind=i4)
            associate (o => g%objects(i))
                if (o%n_cells == 0) cycle
                if (.not. written(i)) then
                    n_left = n_left + o%n_cells
                    cycle
                end if
                t = o%kind
                here = o%line
                call put(' ' // trim(ASTER_NAMES(t)))
                do c = 1, o%n_cells
                    cell = first_cell(i) + c
                    cls = same_as(cell)
                    if (rep(cls) /= cell .and. done(cls)) then
                        n_merged = n_merged + 1
                        cycle
                    end if
                    rep(cls) = cell
                    done(cls) = .true.
                    nodes = g%indirection(o%points((c - 1) * o%n_nodes + 1:c * o%n_nodes))
                    here = o%points_line + int((int(c - 1, i8) * o%n_nodes) / per_line(g), i4)
                    line = '  ' // pad8('M' // to_text(cell))
                    do k = 1, o%n_nodes
                        line = line // ' ' // pad8('N' // to_text(nodes(PERM(k, t))))
                    end do
                    call put(line)
                end do
                call put(' FINSF')
                call put(' %')
            end associate
        end do
        if (n_left > 0) notes = [notes, string_t('GIBI: ' // to_text(n_left) // &
            ' cell(s) of objects no name refers to left out of the mesh (PREPOST5_20)')]
        if (n_merged > 0) notes = [notes, string_t('GIBI: ' // to_text(n_merged) // &
            ' cell(s) given again with the same nodes written once')]
        ! GROUP_NO: the named points
        do i = 1, size(g%point_names, kind=i4)
            if (is_internal(g%point_names(i))) cycle
            here = g%named_points_line + (i - 1) / 8
            call put(' GROUP_NO')
            call put(' ' // g%point_names(i) // ' ' // &
                     pad8('N' // to_text(g%indirection(g%named_points(i)))))
            call put(' FINSF')
            call put(' %')
        end do
        ! GROUP_MA: the named objects in object order, the names of one in their order
        allocate (name_ptr(size(g%objects) + 2), source=0)
        do i = 1, size(g%named_objects, kind=i4)
            j = g%named_objects(i)
            name_ptr(j + 2) = name_ptr(j + 2) + 1
        end do
        do j = 2, size(name_ptr, kind=i4)
            name_ptr(j) = name_ptr(j) + name_ptr(j - 1)
        end do
        allocate (name_list(size(g%named_objects)))
        do i = 1, size(g%named_objects, kind=i4)
            j = g%named_objects(i)
            name_ptr(j + 1) = name_ptr(j + 1) + 1
            name_list(name_ptr(j + 1)) = i
        end do
        do j = 1, size(g%objects, kind=i4)
            do k = name_ptr(j) + 1, name_ptr(j + 1)
                i = name_list(k)
                if (is_internal(g%object_names(i))) cycle
                here = g%pile1_line + 1 + (i - 1) / 8
                call group_of(j, i, trim(adjustl(g%object_names(i))))
            end do
        end do
        here = g%last_line
        call put(' FIN')
        text = join_lines(out(1:n_out))
        origin = origin(1:n_out)
    contains
        subroutine put(s)
            character(len=*), intent(in) :: s
            if (n_out == size(out)) then
                out = [out, out]
                origin = [origin, origin]
            end if
            n_out = n_out + 1
            out(n_out)%s = s
            origin(n_out) = here
        end subroutine put

        ! The cells of object j (or of its sub-objects) by the names they went out under,
        ! each once; an object with none is no group (noted).
        subroutine group_of(j, stamp, name)
            integer(i4), intent(in) :: j, stamp
            character(len=*), intent(in) :: name
            integer(i4), allocatable :: parts(:)
            integer(i4) :: p, q, m, cell, n
            if (g%objects(j)%kind == 0) then
                parts = g%objects(j)%sub
            else
                parts = [j]
            end if
            n = 0
            do p = 1, size(parts)
                q = parts(p)
                do m = first_cell(q) + 1, first_cell(q + 1)
                    cell = rep(same_as(m))
                    if (mark(cell) == stamp) cycle
                    mark(cell) = stamp
                    n = n + 1
                    members(n) = cell
                end do
            end do
            if (n == 0) then
                notes = [notes, string_t('GIBI: object ' // name // ' has no cell: no ' // &
                    'GROUP_MA ' // name)]
                return
            end if
            call put(' GROUP_MA')
            call put('   ' // name)
            line = ''
            do p = 1, n
                line = line // ' ' // pad8('M' // to_text(members(p)))
                if (mod(p, 7) == 0 .or. p == n) then
                    call put(line)
                    line = ''
                end if
            end do
            call put(' FINSF')
            call put(' %')
        end subroutine group_of
    end subroutine write_aster

    ! same_as(c): the first cell (in reading order) with the nodes of cell c in the same
    ! order (gidoma: Cast3M's ET repeats cells), by sorting the cells on their point lists.
    function identical_cells(g, first_cell, n_cells) result(same_as)
        type(gibi_t), intent(in), target :: g
        integer(i4), intent(in) :: first_cell(:), n_cells
        integer(i4), allocatable :: same_as(:)
        type(cell_order_t) :: cells
        integer, allocatable :: order(:)
        integer(i4) :: i, c, k, p
        allocate (cells%start(n_cells), cells%owner(n_cells))
        cells%g => g
        do i = 1, size(g%objects, kind=i4)
            do c = 1, g%objects(i)%n_cells
                k = first_cell(i) + c
                cells%start(k) = (c - 1) * g%objects(i)%n_nodes + 1
                cells%owner(k) = i
            end do
        end do
        call stable_order(n_cells, cells, order)    ! equal cells keep their order
        allocate (same_as(n_cells))
        do p = 1, n_cells
            same_as(order(p)) = order(p)
            if (p > 1) then
                if (cells%compare(order(p - 1), order(p)) == 0) &
                    same_as(order(p)) = same_as(order(p - 1))
            end if
        end do
    end function identical_cells

    ! Cells by their point lists: fewer nodes first, then the first differing point.
    integer function compare_cells(self, a, b) result(c)
        class(cell_order_t), intent(in) :: self
        integer, intent(in) :: a, b
        integer(i4) :: j, pa, pb, na, nb
        na = self%g%objects(self%owner(a))%n_nodes
        nb = self%g%objects(self%owner(b))%n_nodes
        c = 0
        if (na /= nb) then
            c = merge(-1, 1, na < nb)
            return
        end if
        do j = 0, na - 1
            pa = self%g%objects(self%owner(a))%points(self%start(a) + j)
            pb = self%g%objects(self%owner(b))%points(self%start(b) + j)
            if (pa /= pb) then
                c = merge(-1, 1, pa < pb)
                return
            end if
        end do
    end function compare_cells

    ! A name in 8 columns (longer ones as they are).
    function pad8(name) result(text)
        character(len=*), intent(in) :: name
        character(len=max(8, len(name))) :: text
        text = name
    end function pad8

    !> The lines, each ended by a newline, as one text.
    function join_lines(lines) result(text)
        type(string_t), intent(in) :: lines(:)
        character(len=:), allocatable :: text
        integer(i8) :: n
        integer(i4) :: k, p
        n = 0
        do k = 1, size(lines, kind=i4)
            n = n + len(lines(k)%s) + 1
        end do
        allocate (character(len=n) :: text)
        p = 1
        do k = 1, size(lines, kind=i4)
            text(p:p + len(lines(k)%s) - 1) = lines(k)%s
            p = p + len(lines(k)%s)
            text(p:p) = achar(10)
            p = p + 1
        end do
    end function join_lines

end module mesh_gibi_writer
