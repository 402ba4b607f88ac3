!> Fields (field_types) as the viewer writers take them (result_data: VTK point and cell
!> data, Gmsh $NodeData and $ElementData; MED node fields):
!>  - a NOEU field gives a node_field_t (values and mask per component and node);
!>  - a cell field (ELGA, ELNO, ELEM, CART) gives one cell array per component, named
!>    <field>_<component>, holding on each cell the mean of its points (Gauss points, or
!>    nodes for ELNO: a viewer colours a cell by one value); a component that has several
!>    sub-points on some cell (plate layers) gives one array per sub-point,
!>    <field>_<component>_SP<k>, defined on the cells that have that sub-point.
!> Components are NOM_CMP's that the field has (in NOM_CMP's order), or all of them.
module field_viewer_data
    use kinds, only: dp, i4, i8
    use strings, only: string_t, to_text
    use field_types, only: field_t, field_component, FIELD_NOEU
    use result_data, only: node_field_t, cell_array_t
    implicit none
    private

    public :: node_field_of, cell_arrays_of, field_columns

contains

    !> The columns (component indices) of `f` printed for NOM_CMP `names` (empty: all),
    !> leaving out the components no node (NOEU) or no cell of `taken` (cell fields)
    !> carries: a field of several element families (a plate's SIXX .. SIYZ, a spring's N VY
    !> VZ) prints what the cells printed have.
    function field_columns(f, names, taken) result(cols)
        type(field_t), intent(in) :: f
        type(string_t), intent(in) :: names(:)
        logical, intent(in), optional :: taken(:)
        integer(i4), allocatable :: cols(:)
        logical, allocatable :: carried(:)
        integer(i4) :: k, j, n, c
        allocate (carried(size(f%components)), source=.false.)
        if (f%location == FIELD_NOEU) then
            carried = any(f%node_has, dim=2)
        else
            do c = 1, f%n_cells
                if (f%n_points(c) == 0) cycle
                if (present(taken)) then
                    if (c <= size(taken)) then
                        if (.not. taken(c)) cycle
                    end if
                end if
                carried(f%sets(f%cell_set(c))%cmp) = .true.
            end do
        end if
        if (size(names) == 0) then
            cols = pack([(k, k = 1, size(f%components, kind=i4))], carried)
            return
        end if
        allocate (cols(size(names)))
        n = 0
        do k = 1, size(names, kind=i4)
            j = field_component(f, names(k)%s)
            if (j == 0) cycle
            if (.not. carried(j)) cycle
            n = n + 1
            cols(n) = j
        end do
        cols = cols(1:n)
    end function field_columns

    !> A NOEU field as a node_field_t named `name`, with the components of `names`.
    subroutine node_field_of(f, name, names, out)
        type(field_t), intent(in) :: f
        character(len=*), intent(in) :: name
        type(string_t), intent(in) :: names(:)
        type(node_field_t), intent(out) :: out
        integer(i4), allocatable :: cols(:)
        integer(i4) :: j
        cols = field_columns(f, names)
        out%name = name
        allocate (out%components(size(cols)))
        do j = 1, size(cols, kind=i4)
            out%components(j)%s = f%components(cols(j))%s
        end do
        out%values = f%node_values(cols, :)
        out%mask = f%node_has(cols, :)
    end subroutine node_field_of

    !> The cell arrays of a cell field named `name` (module header), on n_cells cells;
    !> `taken` the cells printed (GROUP_MA).
    subroutine cell_arrays_of(f, name, names, taken, arrays)
        type(field_t), intent(in) :: f
        character(len=*), intent(in) :: name
        type(string_t), intent(in) :: names(:)
        logical, intent(in) :: taken(:)
        type(cell_array_t), allocatable, intent(out) :: arrays(:)
        integer(i4), allocatable :: cols(:), max_sub(:)
        integer(i4) :: j, c, q, s, p, n, k, slot, nc
        integer(i8) :: base
        real(dp) :: total
        cols = field_columns(f, names, taken)
        allocate (max_sub(size(cols)), source=0_i4)
        do c = 1, f%n_cells
            if (.not. wanted(c)) cycle
            do j = 1, size(cols, kind=i4)
                if (any(f%sets(f%cell_set(c))%cmp == cols(j))) &
                    max_sub(j) = max(max_sub(j), f%n_subpoints(c))
            end do
        end do
        allocate (arrays(sum(max_sub)))
        k = 0
        do j = 1, size(cols, kind=i4)
            do s = 1, max_sub(j)
                k = k + 1
                arrays(k)%name = name // '_' // f%components(cols(j))%s
                if (max_sub(j) > 1) arrays(k)%name = arrays(k)%name // '_SP' // to_text(s)
                allocate (arrays(k)%values(f%n_cells), source=0.0_dp)
                allocate (arrays(k)%defined(f%n_cells), source=.false.)
                do c = 1, f%n_cells
                    if (.not. wanted(c)) cycle
                    if (s > f%n_subpoints(c)) cycle
                    slot = 0
                    nc = size(f%sets(f%cell_set(c))%cmp, kind=i4)
                    do q = 1, nc
                        if (f%sets(f%cell_set(c))%cmp(q) == cols(j)) slot = q
                    end do
                    if (slot == 0) cycle
                    n = f%n_points(c)
                    total = 0.0_dp
                    do p = 1, n
                        base = f%offset(c) + (int(p - 1, i8) * f%n_subpoints(c) + (s - 1)) * nc
                        total = total + f%values(base + slot)
                    end do
                    arrays(k)%values(c) = total / real(n, dp)
                    arrays(k)%defined(c) = .true.
                end do
            end do
        end do
    contains
        logical function wanted(cell)
            integer(i4), intent(in) :: cell
            wanted = f%n_points(cell) > 0
            if (wanted .and. cell <= size(taken)) wanted = taken(cell)
        end function wanted
    end subroutine cell_arrays_of

end module field_viewer_data
