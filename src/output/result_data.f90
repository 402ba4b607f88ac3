!> Plain data the result writers take (IMPR_RESU: RESULTAT, VTK, GMSH), independent of the
!> mesh and analysis types so that the writers can be wired to any of them:
!>  - a mesh as coords(3, n_nodes), cell types (RESULT_CELL_* below), and the cell-to-node
!>    connectivity in CSR form: the nodes of cell c are cell_nodes(cell_ptr(c):cell_ptr(c+1)-1)
!>    (1-based node numbers, cell_ptr(1) = 1, size(cell_ptr) = n_cells + 1);
!>  - node fields (node_field_t): values(n_components, n_nodes) with component names and a
!>    mask saying which node carries which component (a node without DRZ, a free node).
!> Also the expansion of a node field into the arrays viewers want: DX/DY/DZ as one
!> 3-component vector named after the field (zeros where absent), DRX/DRY/DRZ as a vector
!> `<field>_DR`, any other component as a scalar `<field>_<component>`.
!>  - cell arrays (cell_array_t): one scalar per cell (an element field's component, the
!>    group a cell belongs to, the spring status), with the cells that carry it.
module result_data
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_INTERNAL
    use strings, only: string_t, to_upper
    implicit none
    private

    !> Cell types the writers know (Code_Aster names POI1, SEG2, TRIA3, QUAD4, SEG3, TRIA6,
    !> QUAD8, QUAD9; nodes in Code_Aster's order, which VTK and Gmsh share for these).
    integer, parameter, public :: RESULT_CELL_POI1 = 1, RESULT_CELL_SEG2 = 2, &
                                  RESULT_CELL_TRIA3 = 3, RESULT_CELL_QUAD4 = 4, &
                                  RESULT_CELL_SEG3 = 5, RESULT_CELL_TRIA6 = 6, &
                                  RESULT_CELL_QUAD8 = 7, RESULT_CELL_QUAD9 = 8
    !> Names and node counts of the RESULT_CELL_* codes.
    character(len=5), parameter :: RESULT_CELL_NAMES(8) = ['POI1 ', 'SEG2 ', 'TRIA3', &
        'QUAD4', 'SEG3 ', 'TRIA6', 'QUAD8', 'QUAD9']
    integer, parameter :: RESULT_CELL_NODES(8) = [1, 2, 3, 4, 3, 6, 8, 9]

    !> One field at the nodes at one instant.
    type, public :: node_field_t
        character(len=:), allocatable :: name          !< DEPL, REAC_NODA, ...
        type(string_t), allocatable :: components(:)   !< (n_components) DX, DY, ...
        real(dp), allocatable :: values(:, :)          !< (n_components, n_nodes)
        logical, allocatable :: mask(:, :)             !< (n_components, n_nodes), .true. = has it
    end type node_field_t

    !> A field as viewers want it: a named array of 1 or 3 components per node.
    type, public :: point_array_t
        character(len=:), allocatable :: name
        real(dp), allocatable :: values(:, :)          !< (1 or 3, n_nodes)
    end type point_array_t

    !> One scalar per cell at one instant. `defined` says which cells carry it: the writers
    !> (VTK, Gmsh) put 0 on the others. `whole`: the values
    !> are integers (a group membership, a status), written as such. `constant`: the array
    !> does not change with the instant (Gmsh writes it once, as a view without time).
    type, public :: cell_array_t
        character(len=:), allocatable :: name
        real(dp), allocatable :: values(:)           !< (n_cells)
        logical, allocatable :: defined(:)           !< (n_cells)
        logical :: whole = .false.
        logical :: constant = .false.                !< the same at every instant (a group)
    end type cell_array_t

    public :: cell_type_from_name, cell_type_name, cell_node_count
    public :: check_result_mesh, check_node_field, expand_node_field, check_cell_array

contains

    !> RESULT_CELL_* code of a Code_Aster cell type name (POI1, SEG2, TRIA3, QUAD4, SEG3,
    !> TRIA6, QUAD8, QUAD9), 0 if unknown.
    pure integer function cell_type_from_name(name)
        character(len=*), intent(in) :: name
        integer :: t
        cell_type_from_name = 0
        do t = 1, size(RESULT_CELL_NAMES)
            if (to_upper(trim(name)) == trim(RESULT_CELL_NAMES(t))) cell_type_from_name = t
        end do
    end function cell_type_from_name

    !> Name of a RESULT_CELL_* code ('?' if unknown).
    pure function cell_type_name(cell_type) result(name)
        integer, intent(in) :: cell_type
        character(len=:), allocatable :: name
        name = '?'
        if (cell_type >= 1 .and. cell_type <= size(RESULT_CELL_NAMES)) &
            name = trim(RESULT_CELL_NAMES(cell_type))
    end function cell_type_name

    !> Number of nodes of a RESULT_CELL_* type (0 if unknown).
    elemental integer function cell_node_count(cell_type)
        integer, intent(in) :: cell_type
        cell_node_count = 0
        if (cell_type >= 1 .and. cell_type <= size(RESULT_CELL_NODES)) &
            cell_node_count = RESULT_CELL_NODES(cell_type)
    end function cell_node_count

    !> Checks the shapes and contents of a mesh given to a writer.
    !>  coords      : in, (3, n_nodes)
    !>  cell_types  : in, (n_cells) RESULT_CELL_* codes
    !>  cell_ptr    : in, (n_cells + 1) CSR pointers, cell_ptr(1) = 1
    !>  cell_nodes  : in, node numbers, 1 .. n_nodes
    !>  st          : out, STATUS_INTERNAL saying what is inconsistent (a caller's bug)
    subroutine check_result_mesh(coords, cell_types, cell_ptr, cell_nodes, st)
        real(dp), intent(in) :: coords(:, :)
        integer, intent(in) :: cell_types(:), cell_ptr(:), cell_nodes(:)
        type(status_t), intent(out) :: st
        integer :: c
        character(len=16) :: buf
        if (size(coords, 1) /= 3) then
            call set_error(st, STATUS_INTERNAL, 'result mesh: coords must be (3, n_nodes)')
            return
        end if
        if (size(cell_ptr) /= size(cell_types) + 1) then
            call set_error(st, STATUS_INTERNAL, &
                           'result mesh: cell_ptr must have n_cells + 1 entries')
            return
        end if
        if (cell_ptr(1) /= 1 .or. cell_ptr(size(cell_ptr)) - 1 > size(cell_nodes)) then
            call set_error(st, STATUS_INTERNAL, 'result mesh: cell_ptr must start at 1 and ' // &
                           'end within cell_nodes')
            return
        end if
        do c = 1, size(cell_types)
            write (buf, '(i0)') c
            if (cell_node_count(cell_types(c)) == 0 .or. &
                cell_ptr(c + 1) - cell_ptr(c) /= cell_node_count(cell_types(c))) then
                call set_error(st, STATUS_INTERNAL, 'result mesh: cell ' // trim(buf) // &
                               ' has an unknown type or the wrong number of nodes')
                return
            end if
            if (any(cell_nodes(cell_ptr(c):cell_ptr(c + 1) - 1) < 1) .or. &
                any(cell_nodes(cell_ptr(c):cell_ptr(c + 1) - 1) > size(coords, 2))) then
                call set_error(st, STATUS_INTERNAL, 'result mesh: cell ' // trim(buf) // &
                               ' refers to a node that does not exist')
                return
            end if
        end do
    end subroutine check_result_mesh

    !> Checks that a field has a name, one name per component and values and mask of shape
    !> (n_components, n_nodes).
    !>  field   : in, the field
    !>  n_nodes : in, the number of nodes of the mesh
    !>  st      : out, STATUS_INTERNAL naming the field when inconsistent
    subroutine check_node_field(field, n_nodes, st)
        type(node_field_t), intent(in) :: field
        integer, intent(in) :: n_nodes
        type(status_t), intent(out) :: st
        integer :: n_cmp
        if (.not. (allocated(field%name) .and. allocated(field%components) .and. &
                   allocated(field%values) .and. allocated(field%mask))) then
            call set_error(st, STATUS_INTERNAL, 'result field: name, components, values ' // &
                           'and mask must all be set')
            return
        end if
        n_cmp = size(field%components)
        if (size(field%values, 1) /= n_cmp .or. size(field%values, 2) /= n_nodes .or. &
            size(field%mask, 1) /= n_cmp .or. size(field%mask, 2) /= n_nodes) then
            call set_error(st, STATUS_INTERNAL, 'result field ' // field%name // &
                           ': values and mask must be (n_components, n_nodes)')
        end if
    end subroutine check_node_field

    !> Checks that a cell array has a name and values and `defined` of size n_cells, with
    !> finite values on the cells that carry it.
    !>  st : out, STATUS_INTERNAL naming the array (a caller's bug: the fields are checked
    !>       finite when they are built)
    subroutine check_cell_array(array, n_cells, st)
        use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
        type(cell_array_t), intent(in) :: array
        integer, intent(in) :: n_cells
        type(status_t), intent(out) :: st
        if (.not. (allocated(array%name) .and. allocated(array%values) .and. &
                   allocated(array%defined))) then
            call set_error(st, STATUS_INTERNAL, 'cell array: name, values and defined ' // &
                           'must all be set')
            return
        end if
        if (size(array%values) /= n_cells .or. size(array%defined) /= n_cells) then
            call set_error(st, STATUS_INTERNAL, 'cell array ' // array%name // &
                           ': values and defined must have one entry per cell')
            return
        end if
        if (.not. all(ieee_is_finite(array%values) .or. .not. array%defined)) &
            call set_error(st, STATUS_INTERNAL, 'cell array ' // array%name // &
                           ': a value is not a finite number')
    end subroutine check_cell_array

    !> Expands a node field into viewer arrays (see the module header): a vector named after
    !> the field from DX/DY/DZ, `<field>_DR` from DRX/DRY/DRZ, scalars `<field>_<cmp>` for the
    !> rest; absent components (mask false or not in the field) are zeros.
    !>  field  : in, a field that passed check_node_field
    !>  arrays : out, the arrays, vectors first
    pure subroutine expand_node_field(field, arrays)
        type(node_field_t), intent(in) :: field
        type(point_array_t), allocatable, intent(out) :: arrays(:)
        character(len=3), parameter :: translations(3) = ['DX ', 'DY ', 'DZ ']
        character(len=3), parameter :: rotations(3) = ['DRX', 'DRY', 'DRZ']
        logical :: used(size(field%components))
        type(point_array_t) :: found(size(field%components) + 2)
        integer :: n_found, k
        used = .false.
        n_found = 0
        call gather_vector(field, translations, field%name, used, found, n_found)
        call gather_vector(field, rotations, field%name // '_DR', used, found, n_found)
        do k = 1, size(field%components)
            if (used(k)) cycle
            n_found = n_found + 1
            found(n_found)%name = field%name // '_' // trim(field%components(k)%s)
            found(n_found)%values = reshape(merge(field%values(k, :), 0.0_dp, &
                                                  field%mask(k, :)), [1, size(field%values, 2)])
        end do
        arrays = found(1:n_found)
    end subroutine expand_node_field

    !> Adds the vector made of components `names` when the field has any of them.
    pure subroutine gather_vector(field, names, array_name, used, found, n_found)
        type(node_field_t), intent(in) :: field
        character(len=*), intent(in) :: names(3), array_name
        logical, intent(inout) :: used(:)
        type(point_array_t), intent(inout) :: found(:)
        integer, intent(inout) :: n_found
        integer :: d, k
        logical :: any_found
        any_found = .false.
        do k = 1, size(field%components)
            if (any(to_upper(trim(field%components(k)%s)) == names)) any_found = .true.
        end do
        if (.not. any_found) return
        n_found = n_found + 1
        found(n_found)%name = array_name
        allocate (found(n_found)%values(3, size(field%values, 2)))
        found(n_found)%values = 0.0_dp
        do k = 1, size(field%components)
            do d = 1, 3
                if (to_upper(trim(field%components(k)%s)) /= names(d)) cycle
                used(k) = .true.
                found(n_found)%values(d, :) = merge(field%values(k, :), 0.0_dp, field%mask(k, :))
            end do
        end do
    end subroutine gather_vector

end module result_data
