!> The field model (doc/architecture.md, "Fields and results"): one type, field_t, for every
!> kind of Code_Aster field parasol handles, named by its location (the first word of a
!> TYPE_CHAM) and its physical quantity (field_quantities):
!>   NOEU  values at the nodes: values(n_components, n_nodes) with a mask saying which node
!>         carries which component (a node has only the components its elements use);
!>   ELGA  values at the integration points of each cell (the Gauss family of its element,
!>         points in Code_Aster's order), and per point at sub-points (plate layers: three
!>         per layer, INF, MOY, SUP, layer by layer from the bottom);
!>   ELNO  values at the nodes of each cell (points = the cell's nodes in its order), with
!>         sub-points as ELGA;
!>   ELEM  one value set per cell;
!>   CART  constant by zone (a "carte"): one value set per cell, as ELEM.
!> A cell field has, per cell, a number of points, of sub-points and a component set (a
!> subset of the field's components: a plate's SIEF_ELGA holds NXX .. QY, a spring's
!> N VY VZ); cells outside the field have 0 points. Values are stored cell by cell, point
!> by point, sub-point by sub-point, component by component (the component index varies
!> fastest), the storage of Code_Aster's CHAM_ELEM.
!>
!> A field knows node and cell NUMBERS only, not the mesh: the concept that holds it
!> (field_concept, result_fields) knows which mesh they belong to. Function-valued fields
!> (quantities *_F) store in each value the index of a function in `functions`.
module field_types
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_INTERNAL
    use strings, only: string_t, to_text, to_upper
    use function_concept, only: function_concept_t
    use field_quantities, only: is_quantity, quantity_components, quantity_component_index, &
        quantity_is_function, components_text
    implicit none
    private

    !> Locations (the first word of TYPE_CHAM). FIELD_NONE: an empty field.
    integer(i4), parameter, public :: FIELD_NONE = 0, FIELD_NOEU = 1, FIELD_ELGA = 2, &
        FIELD_ELNO = 3, FIELD_ELEM = 4, FIELD_CART = 5
    character(len=4), parameter, public :: FIELD_LOCATION_NAMES(5) = ['NOEU', 'ELGA', &
        'ELNO', 'ELEM', 'CART']

    !> A function held by a function-valued field (owned by the run context).
    type, public :: function_ref_t
        class(function_concept_t), pointer :: f => null()
    end type function_ref_t

    !> The components a group of cells holds: indices into field%components, ascending.
    type, public :: component_set_t
        integer(i4), allocatable :: cmp(:)
    end type component_set_t

    type, public :: field_t
        integer(i4) :: location = FIELD_NONE
        character(len=:), allocatable :: quantity         !< DEPL_R, SIEF_R, ...
        type(string_t), allocatable :: components(:)       !< in the quantity's order
        integer(i4) :: n_nodes = 0, n_cells = 0
        ! ---- NOEU ----
        real(dp), allocatable :: node_values(:, :)         !< (n_components, n_nodes)
        logical, allocatable :: node_has(:, :)             !< (n_components, n_nodes)
        ! ---- ELGA, ELNO, ELEM, CART ----
        integer(i4), allocatable :: n_points(:)            !< (n_cells), 0: not in the field
        integer(i4), allocatable :: n_subpoints(:)         !< (n_cells), >= 1 when in it
        integer(i4), allocatable :: cell_set(:)            !< (n_cells) index into sets
        type(component_set_t), allocatable :: sets(:)
        integer(i8), allocatable :: offset(:)              !< (n_cells + 1), 0-based starts
        real(dp), allocatable :: values(:)
        !> ELGA: the Gauss family of the points (Code_Aster's RIGI for the stiffness points).
        character(len=:), allocatable :: family
        ! ---- function-valued quantities (*_F) ----
        type(function_ref_t), allocatable :: functions(:)
    end type field_t

    public :: field_init_nodes, field_init_cells, field_define_cells, field_component, &
        field_position, field_node_value, field_cell_value, field_type_cham, &
        parse_type_cham, field_cell_components, field_is_cell_field, field_add_function, &
        field_values_of, field_location_name, field_node_components, field_check_finite

contains

    !> An empty NOEU field of `quantity` with `components` on n_nodes nodes (no node
    !> carries a component yet).
    !>  st : STATUS_INTERNAL for an unknown quantity or component (a caller's bug: deck
    !>       input is checked before)
    subroutine field_init_nodes(f, quantity, components, n_nodes, st)
        type(field_t), intent(out) :: f
        character(len=*), intent(in) :: quantity
        type(string_t), intent(in) :: components(:)
        integer(i4), intent(in) :: n_nodes
        type(status_t), intent(out) :: st
        call set_components(f, quantity, components, st)
        if (st%failed()) return
        f%location = FIELD_NOEU
        f%n_nodes = n_nodes
        allocate (f%node_values(size(f%components), n_nodes), source=0.0_dp)
        allocate (f%node_has(size(f%components), n_nodes), source=.false.)
        if (quantity_is_function(quantity)) allocate (f%functions(0))
    end subroutine field_init_nodes

    !> An empty cell field (ELGA, ELNO, ELEM or CART) of `quantity` with `components` on
    !> n_cells cells; field_define_cells then gives each cell its points and components.
    subroutine field_init_cells(f, location, quantity, components, n_cells, st)
        type(field_t), intent(out) :: f
        integer(i4), intent(in) :: location
        character(len=*), intent(in) :: quantity
        type(string_t), intent(in) :: components(:)
        integer(i4), intent(in) :: n_cells
        type(status_t), intent(out) :: st
        if (location < FIELD_ELGA .or. location > FIELD_CART) then
            call set_error(st, STATUS_INTERNAL, 'field_init_cells: not a cell location')
            return
        end if
        call set_components(f, quantity, components, st)
        if (st%failed()) return
        f%location = location
        f%n_cells = n_cells
        allocate (f%n_points(n_cells), f%n_subpoints(n_cells), f%cell_set(n_cells), &
            source=0_i4)
        allocate (f%offset(n_cells + 1), source=0_i8)
        allocate (f%sets(0), f%values(0))
        f%family = ''
        if (location == FIELD_ELGA) f%family = 'RIGI'
        if (quantity_is_function(quantity)) allocate (f%functions(0))
    end subroutine field_init_cells

    !> Gives each cell its layout and allocates the values (zeros).
    !>  n_points    : in, (n_cells) points per cell, 0 for a cell outside the field
    !>  n_subpoints : in, (n_cells) sub-points per point (1 without layers)
    !>  cell_set    : in, (n_cells) index into `sets` of the cell's components
    !>  sets        : in, the component sets (indices into f%components, ascending)
    !>  st          : STATUS_INTERNAL for inconsistent sizes
    subroutine field_define_cells(f, n_points, n_subpoints, cell_set, sets, st)
        type(field_t), intent(inout) :: f
        integer(i4), intent(in) :: n_points(:), n_subpoints(:), cell_set(:)
        type(component_set_t), intent(in) :: sets(:)
        type(status_t), intent(out) :: st
        integer(i4) :: c
        integer(i8) :: n
        if (size(n_points) /= f%n_cells .or. size(n_subpoints) /= f%n_cells .or. &
            size(cell_set) /= f%n_cells) then
            call set_error(st, STATUS_INTERNAL, 'field_define_cells: one entry per cell')
            return
        end if
        f%sets = sets
        f%n_points = max(n_points, 0_i4)
        f%n_subpoints = max(n_subpoints, 1_i4)
        f%cell_set = cell_set
        f%offset(1) = 0
        do c = 1, f%n_cells
            n = 0
            if (f%n_points(c) > 0) then
                if (cell_set(c) < 1 .or. cell_set(c) > size(sets)) then
                    call set_error(st, STATUS_INTERNAL, 'field_define_cells: cell ' // &
                        to_text(c) // ' has no component set')
                    return
                end if
                n = int(f%n_points(c), i8) * f%n_subpoints(c) * size(sets(cell_set(c))%cmp)
            else
                f%cell_set(c) = 0
            end if
            f%offset(c + 1) = f%offset(c) + n
        end do
        if (allocated(f%values)) deallocate (f%values)
        allocate (f%values(f%offset(f%n_cells + 1)), source=0.0_dp)
    end subroutine field_define_cells

    !> Checks the quantity and components and stores them in the quantity's order.
    subroutine set_components(f, quantity, components, st)
        type(field_t), intent(inout) :: f
        character(len=*), intent(in) :: quantity
        type(string_t), intent(in) :: components(:)
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: rank(:)
        integer(i4) :: k, j, tmp
        type(string_t) :: swap
        if (.not. is_quantity(to_upper(quantity))) then
            call set_error(st, STATUS_INTERNAL, 'unknown physical quantity ' // quantity)
            return
        end if
        f%quantity = to_upper(trim(quantity))
        allocate (rank(size(components)))
        do k = 1, size(components)
            rank(k) = quantity_component_index(f%quantity, components(k)%s)
            if (rank(k) == 0) then
                call set_error(st, STATUS_INTERNAL, f%quantity // ' has no component ' // &
                    components(k)%s)
                return
            end if
        end do
        f%components = components
        do k = 1, size(f%components)
            f%components(k)%s = to_upper(trim(f%components(k)%s))
        end do
        do k = 2, size(rank)              ! insertion sort: a handful of components
            j = k
            do while (j > 1)
                if (rank(j - 1) <= rank(j)) exit
                tmp = rank(j - 1); rank(j - 1) = rank(j); rank(j) = tmp
                swap = f%components(j - 1); f%components(j - 1) = f%components(j)
                f%components(j) = swap
                j = j - 1
            end do
        end do
        do k = 2, size(rank)
            if (rank(k) == rank(k - 1)) then
                call set_error(st, STATUS_INTERNAL, 'component ' // f%components(k)%s // &
                    ' given twice')
                return
            end if
        end do
    end subroutine set_components

    !> Index of component `name` in f%components, 0 when the field has no such component.
    pure integer(i4) function field_component(f, name) result(k)
        type(field_t), intent(in) :: f
        character(len=*), intent(in) :: name
        k = 0
        if (.not. allocated(f%components)) return
        do k = 1, size(f%components, kind=i4)
            if (f%components(k)%s == to_upper(trim(name))) return
        end do
        k = 0
    end function field_component

    !> Position in f%values of (cell, point, sub-point, component k of the field), 0 when
    !> the cell does not hold that component or the point/sub-point is out of its range.
    pure integer(i8) function field_position(f, cell, point, subpoint, k) result(pos)
        type(field_t), intent(in) :: f
        integer(i4), intent(in) :: cell, point, subpoint, k
        integer(i4) :: j, n_cmp
        pos = 0
        if (cell < 1 .or. cell > f%n_cells) return
        if (f%n_points(cell) == 0) return
        if (point < 1 .or. point > f%n_points(cell)) return
        if (subpoint < 1 .or. subpoint > f%n_subpoints(cell)) return
        associate (cmps => f%sets(f%cell_set(cell))%cmp)
            n_cmp = size(cmps, kind=i4)
            do j = 1, n_cmp
                if (cmps(j) == k) then
                    pos = f%offset(cell) + (int(point - 1, i8) * f%n_subpoints(cell) + &
                        (subpoint - 1)) * n_cmp + j
                    return
                end if
            end do
        end associate
    end function field_position

    !> The value of component `name` at node `node` of a NOEU field.
    !>  st : STATUS_MODEL_ERROR saying which components exist (in the field, at the node)
    subroutine field_node_value(f, node, name, value, st)
        type(field_t), intent(in) :: f
        integer(i4), intent(in) :: node
        character(len=*), intent(in) :: name
        real(dp), intent(out) :: value
        type(status_t), intent(out) :: st
        integer(i4) :: k
        value = 0.0_dp
        if (f%location /= FIELD_NOEU) then
            call set_error(st, STATUS_MODEL_ERROR, 'the field is not a nodal field ' // &
                '(it is ' // field_location_name(f) // ')')
            return
        end if
        k = field_component(f, name)
        if (k == 0) then
            call set_error(st, STATUS_MODEL_ERROR, 'the field has no component ' // &
                trim(name) // ' (it has ' // components_text(f%components) // ')')
            return
        end if
        if (node < 1 .or. node > f%n_nodes) then
            call set_error(st, STATUS_INTERNAL, 'node number ' // to_text(node) // &
                ' is not in the field')
            return
        end if
        if (.not. f%node_has(k, node)) then
            call set_error(st, STATUS_MODEL_ERROR, 'the node has no component ' // &
                trim(name) // ' (it has ' // field_node_components(f, node) // ')')
            return
        end if
        value = f%node_values(k, node)
    end subroutine field_node_value

    !> The components node `node` carries, as text ('none' when it carries none).
    function field_node_components(f, node) result(text)
        type(field_t), intent(in) :: f
        integer(i4), intent(in) :: node
        character(len=:), allocatable :: text
        integer(i4) :: k
        text = ''
        do k = 1, size(f%components, kind=i4)
            if (.not. f%node_has(k, node)) cycle
            if (len(text) > 0) text = text // ' '
            text = text // f%components(k)%s
        end do
        if (len(text) == 0) text = 'none'
    end function field_node_components

    !> The components cell `cell` holds in a cell field, as text ('none' outside it).
    function field_cell_components(f, cell) result(text)
        type(field_t), intent(in) :: f
        integer(i4), intent(in) :: cell
        character(len=:), allocatable :: text
        integer(i4) :: j
        text = 'none'
        if (cell < 1 .or. cell > f%n_cells) return
        if (f%n_points(cell) == 0) return
        text = ''
        associate (cmps => f%sets(f%cell_set(cell))%cmp)
            do j = 1, size(cmps)
                if (j > 1) text = text // ' '
                text = text // f%components(cmps(j))%s
            end do
        end associate
    end function field_cell_components

    !> The value of component `name` at (cell, point, sub-point) of a cell field.
    !>  st : STATUS_MODEL_ERROR naming what exists: the cell is not in the field, the point
    !>       or sub-point beyond the cell's, the component not held by the cell
    subroutine field_cell_value(f, cell, point, subpoint, name, value, st)
        type(field_t), intent(in) :: f
        integer(i4), intent(in) :: cell, point, subpoint
        character(len=*), intent(in) :: name
        real(dp), intent(out) :: value
        type(status_t), intent(out) :: st
        integer(i4) :: k
        integer(i8) :: pos
        value = 0.0_dp
        if (.not. field_is_cell_field(f)) then
            call set_error(st, STATUS_MODEL_ERROR, 'the field is not an element field ' // &
                '(it is ' // field_location_name(f) // ')')
            return
        end if
        if (cell < 1 .or. cell > f%n_cells) then
            call set_error(st, STATUS_INTERNAL, 'cell number ' // to_text(cell) // &
                ' is not in the field')
            return
        end if
        if (f%n_points(cell) == 0) then
            call set_error(st, STATUS_MODEL_ERROR, 'the field has no value on the cell ' // &
                '(its element does not compute it)')
            return
        end if
        if (point < 1 .or. point > f%n_points(cell)) then
            call set_error(st, STATUS_MODEL_ERROR, 'POINT ' // to_text(point) // &
                ' does not exist: the cell has ' // to_text(f%n_points(cell)) // ' ' // &
                point_words(f) // ' (POINT 1 to ' // to_text(f%n_points(cell)) // ')')
            return
        end if
        if (subpoint < 1 .or. subpoint > f%n_subpoints(cell)) then
            call set_error(st, STATUS_MODEL_ERROR, 'SOUS_POINT ' // to_text(subpoint) // &
                ' does not exist: the cell has ' // to_text(f%n_subpoints(cell)) // &
                ' sub-point(s) per point (SOUS_POINT 1 to ' // &
                to_text(f%n_subpoints(cell)) // ')')
            return
        end if
        k = field_component(f, name)
        pos = 0
        if (k > 0) pos = field_position(f, cell, point, subpoint, k)
        if (pos == 0) then
            call set_error(st, STATUS_MODEL_ERROR, 'the cell has no component ' // &
                trim(name) // ' in this field (it has ' // field_cell_components(f, cell) // &
                ')')
            return
        end if
        value = f%values(pos)
    end subroutine field_cell_value

    !> What the points of a field are, for messages.
    pure function point_words(f) result(text)
        type(field_t), intent(in) :: f
        character(len=:), allocatable :: text
        select case (f%location)
        case (FIELD_ELGA)
            text = 'Gauss point(s)'
        case (FIELD_ELNO)
            text = 'node(s)'
        case default
            text = 'point(s)'
        end select
    end function point_words

    !> True for ELGA, ELNO, ELEM and CART fields.
    elemental logical function field_is_cell_field(f)
        type(field_t), intent(in) :: f
        field_is_cell_field = f%location >= FIELD_ELGA .and. f%location <= FIELD_CART
    end function field_is_cell_field

    !> The location word (NOEU, ELGA, ...), 'empty' for an empty field.
    pure function field_location_name(f) result(text)
        type(field_t), intent(in) :: f
        character(len=:), allocatable :: text
        text = 'empty'
        if (f%location >= 1 .and. f%location <= size(FIELD_LOCATION_NAMES)) &
            text = FIELD_LOCATION_NAMES(f%location)
    end function field_location_name

    !> The TYPE_CHAM of a field: <location>_<quantity> (NOEU_DEPL_R, ELGA_SIEF_R, ...).
    pure function field_type_cham(f) result(text)
        type(field_t), intent(in) :: f
        character(len=:), allocatable :: text
        text = field_location_name(f)
        if (allocated(f%quantity)) text = text // '_' // f%quantity
    end function field_type_cham

    !> Splits a TYPE_CHAM into its location and quantity.
    !>  st : STATUS_MODEL_ERROR for an unknown location or quantity, naming the known ones
    subroutine parse_type_cham(text, location, quantity, st)
        character(len=*), intent(in) :: text
        integer(i4), intent(out) :: location
        character(len=:), allocatable, intent(out) :: quantity
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: t
        integer(i4) :: k
        location = FIELD_NONE
        quantity = ''
        t = to_upper(trim(text))
        if (len(t) > 5) then
            do k = 1, size(FIELD_LOCATION_NAMES, kind=i4)
                if (t(1:5) == FIELD_LOCATION_NAMES(k) // '_') location = k
            end do
            quantity = t(6:)
        end if
        if (location == FIELD_NONE) then
            call set_error(st, STATUS_MODEL_ERROR, 'TYPE_CHAM ' // t // ' does not start ' // &
                'with a location (NOEU_, ELGA_, ELNO_, ELEM_ or CART_)')
            return
        end if
        if (.not. is_quantity(quantity)) then
            call set_error(st, STATUS_MODEL_ERROR, 'TYPE_CHAM ' // t // ': parasol has no ' // &
                'physical quantity ' // quantity // ' (it knows DEPL_R DEPL_F SIEF_R EPSI_R ' // &
                'TEMP_R TEMP_F NEUT_R NEUT_F GEOM_R ENER_R VARI_R HYDR_R ERRE_R SING_R ' // &
                'FER2_R FORC_R FORC_F PRES_R PRES_F)')
            return
        end if
    end subroutine parse_type_cham

    !> Adds a function to a function-valued field; returns its index (the value to store).
    subroutine field_add_function(f, fn, index)
        type(field_t), intent(inout) :: f
        class(function_concept_t), pointer, intent(in) :: fn
        real(dp), intent(out) :: index
        type(function_ref_t), allocatable :: bigger(:)
        integer :: k
        if (.not. allocated(f%functions)) allocate (f%functions(0))
        do k = 1, size(f%functions)
            if (associated(f%functions(k)%f, fn)) then
                index = real(k, dp)
                return
            end if
        end do
        allocate (bigger(size(f%functions) + 1))
        bigger(1:size(f%functions)) = f%functions
        bigger(size(bigger))%f => fn
        call move_alloc(bigger, f%functions)
        index = real(size(f%functions), dp)
    end subroutine field_add_function

    !> Every value of the field for the components `names` (all components when absent):
    !> the node values a node carries, the cell values at every point and sub-point. Used
    !> by TEST_RESU TYPE_TEST (sums, extremes over a whole field).
    !>  cells : in, optional, restricts a cell field to these cells (a NOEU field to the
    !>          nodes when `nodes` is given)
    !>  st    : STATUS_MODEL_ERROR for a component the field lacks
    subroutine field_values_of(f, values, st, names, cells, nodes)
        type(field_t), intent(in) :: f
        real(dp), allocatable, intent(out) :: values(:)
        type(status_t), intent(out) :: st
        type(string_t), intent(in), optional :: names(:)
        integer(i4), intent(in), optional :: cells(:), nodes(:)
        logical, allocatable :: wanted(:), cell_wanted(:), node_wanted(:)
        integer(i4) :: k, c, p, s, j, n_cmp
        integer(i8) :: n, base
        allocate (wanted(size(f%components)), source=.not. present(names))
        if (present(names)) then
            do j = 1, size(names)
                k = field_component(f, names(j)%s)
                if (k == 0) then
                    call set_error(st, STATUS_MODEL_ERROR, 'the field has no component ' // &
                        names(j)%s // ' (it has ' // components_text(f%components) // ')')
                    allocate (values(0))
                    return
                end if
                wanted(k) = .true.
            end do
        end if
        if (f%location == FIELD_NOEU) then
            allocate (node_wanted(f%n_nodes), source=.not. present(nodes))
            if (present(nodes)) node_wanted(nodes) = .true.
            values = pack(f%node_values, f%node_has .and. spread(wanted, 2, f%n_nodes) .and. &
                spread(node_wanted, 1, size(wanted)))
            return
        end if
        allocate (cell_wanted(f%n_cells), source=.not. present(cells))
        if (present(cells)) cell_wanted(cells) = .true.
        n = 0
        allocate (values(size(f%values, kind=i8)))
        do c = 1, f%n_cells
            if (f%n_points(c) == 0 .or. .not. cell_wanted(c)) cycle
            associate (cmps => f%sets(f%cell_set(c))%cmp)
                n_cmp = size(cmps, kind=i4)
                do p = 1, f%n_points(c)
                    do s = 1, f%n_subpoints(c)
                        base = f%offset(c) + (int(p - 1, i8) * f%n_subpoints(c) + (s - 1)) * &
                            n_cmp
                        do j = 1, n_cmp
                            if (.not. wanted(cmps(j))) cycle
                            n = n + 1
                            values(n) = f%values(base + j)
                        end do
                    end do
                end do
            end associate
        end do
        values = values(1:n)
    end subroutine field_values_of

    !> STATUS_MODEL_ERROR naming the first entity (node or cell number) whose value is not a
    !> finite number (a field never carries NaN or Inf into a listing).
    subroutine field_check_finite(f, st)
        use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
        type(field_t), intent(in) :: f
        type(status_t), intent(out) :: st
        integer(i4) :: c, n
        if (allocated(f%functions)) return
        if (f%location == FIELD_NOEU) then
            do n = 1, f%n_nodes
                if (all(ieee_is_finite(f%node_values(:, n)) .or. .not. f%node_has(:, n))) cycle
                call set_error(st, STATUS_MODEL_ERROR, 'a value of node number ' // &
                    to_text(n) // ' is not a finite number')
                return
            end do
        else if (field_is_cell_field(f)) then
            do c = 1, f%n_cells
                if (all(ieee_is_finite(f%values(f%offset(c) + 1:f%offset(c + 1))))) cycle
                call set_error(st, STATUS_MODEL_ERROR, 'a value of cell number ' // &
                    to_text(c) // ' is not a finite number')
                return
            end do
        end if
    end subroutine field_check_finite

end module field_types
