!> The cell data IMPR_RESU writes for viewers (VTK CellData, Gmsh $ElementData), built from a
!> result (analysis_result):
!>  - the spring fields, one scalar array per component: SIEF_ELGA_N, SIEF_ELGA_VY,
!>    SIEF_ELGA_VZ (3D), VARI_ELGA_V1 .. VARI_ELGA_V10, carried by the DIS_CHOC springs
!>    (both Gauss points of a spring hold the same value, so one value per cell);
!>  - SPRING_STATUS, with the spring fields: 1 closed (in contact), 2 open, carried by the
!>    springs (VTK writes 0 on the other cells, so that colouring by it shows the open and
!>    the closed springs and the rest of the mesh apart at once);
!>  - GROUP_<name> for every cell group of the mesh: 1 on its cells (the group of each cell,
!>    to threshold or colour by in a viewer).
!> NOM_CMP splits between the fields (split_components): DX .. DRZ restrict the node
!> fields, N VY VZ SIEF_ELGA, V1 .. V10 VARI_ELGA.
module result_cell_arrays
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: string_t, to_upper, join_words
    use mesh_types, only: mesh_t, n_cell_groups, cell_group_name, cells_of_group
    use model_dof_numbering, only: component_index
    use element_spring_fields, only: SIEF_COMPONENTS, DIS_CHOC_N_VARI, &
        sief_component_index, vari_component_index, vari_name
    use analysis_result, only: result_concept_t, is_cell_field
    use result_data, only: cell_array_t
    implicit none
    private

    !> SPRING_STATUS values.
    real(dp), parameter, public :: SPRING_STATUS_CLOSED = 1.0_dp, SPRING_STATUS_OPEN = 2.0_dp

    public :: spring_cell_arrays, group_cell_arrays, split_components, field_components

contains

    !> The cell arrays of one element field at stored instant `stored`, then SPRING_STATUS.
    !>  field      : in, SIEF_ELGA or VARI_ELGA
    !>  components : in, its components to write (empty: all)
    !>  arrays     : out, one per component, then SPRING_STATUS
    subroutine spring_cell_arrays(res, stored, field, components, arrays)
        type(result_concept_t), intent(in) :: res
        integer(i4), intent(in) :: stored
        character(len=*), intent(in) :: field
        type(string_t), intent(in) :: components(:)
        type(cell_array_t), allocatable, intent(out) :: arrays(:)
        type(string_t), allocatable :: names(:)
        integer(i4) :: a, k, c, n_cells
        n_cells = res%mesh%n_cells
        names = components
        if (size(names) == 0) names = field_components(res, field)
        allocate (arrays(size(names) + 1))
        do a = 1, size(names)
            arrays(a)%name = field // '_' // names(a)%s
            allocate (arrays(a)%values(n_cells), source=0.0_dp)
            allocate (arrays(a)%defined(n_cells), source=.false.)
            if (field == 'SIEF_ELGA') then
                c = sief_component_index(names(a)%s, res%spring_dim)
            else
                c = vari_component_index(names(a)%s, DIS_CHOC_N_VARI)
            end if
            do k = 1, size(res%spring_cell)
                arrays(a)%defined(res%spring_cell(k)) = .true.
                if (field == 'SIEF_ELGA') then
                    arrays(a)%values(res%spring_cell(k)) = res%spring_sief(c, k, stored)
                else
                    arrays(a)%values(res%spring_cell(k)) = res%spring_vari(c, k, stored)
                end if
            end do
        end do
        a = size(names) + 1
        arrays(a)%name = 'SPRING_STATUS'
        arrays(a)%whole = .true.
        allocate (arrays(a)%values(n_cells), source=0.0_dp)
        allocate (arrays(a)%defined(n_cells), source=.false.)
        do k = 1, size(res%spring_cell)
            arrays(a)%defined(res%spring_cell(k)) = .true.
            arrays(a)%values(res%spring_cell(k)) = merge(SPRING_STATUS_CLOSED, &
                SPRING_STATUS_OPEN, res%spring_closed(k, stored))
        end do
    end subroutine spring_cell_arrays

    !> GROUP_<name> (whole, 1 on the group's cells) for every cell group of the mesh.
    subroutine group_cell_arrays(mesh, arrays)
        type(mesh_t), intent(in) :: mesh
        type(cell_array_t), allocatable, intent(out) :: arrays(:)
        integer(i4) :: g
        allocate (arrays(n_cell_groups(mesh)))
        do g = 1, size(arrays, kind=i4)
            arrays(g)%name = 'GROUP_' // cell_group_name(mesh, g)
            arrays(g)%whole = .true.
            arrays(g)%constant = .true.
            allocate (arrays(g)%values(mesh%n_cells), source=0.0_dp)
            allocate (arrays(g)%defined(mesh%n_cells), source=.false.)
            arrays(g)%values(cells_of_group(mesh, g)) = 1.0_dp
            arrays(g)%defined(cells_of_group(mesh, g)) = .true.
        end do
    end subroutine group_cell_arrays

    !> Every component of an element field of `res`: N VY VZ (N VY in 2D) or V1 .. V10.
    function field_components(res, field) result(names)
        type(result_concept_t), intent(in) :: res
        character(len=*), intent(in) :: field
        type(string_t), allocatable :: names(:)
        integer(i4) :: k
        if (field == 'SIEF_ELGA') then
            allocate (names(res%spring_dim))
            do k = 1, res%spring_dim
                names(k)%s = trim(SIEF_COMPONENTS(k))
            end do
        else
            allocate (names(DIS_CHOC_N_VARI))
            do k = 1, DIS_CHOC_N_VARI
                names(k)%s = vari_name(k)
            end do
        end if
    end function field_components

    !> Splits NOM_CMP among the fields asked for: node components (DX .. DRZ), SIEF_ELGA's
    !> (N VY VZ) and VARI_ELGA's (V1 .. V10). An empty list stays empty for each (all).
    !>  st : out, STATUS_MODEL_ERROR for a name that is no component of any field asked for,
    !>       or when the list names none of a field's components; element fields asked of a
    !>       result without DIS_CHOC springs
    subroutine split_components(res, fields, components, node_cmps, sief_cmps, vari_cmps, st)
        type(result_concept_t), intent(in) :: res
        type(string_t), intent(in) :: fields(:), components(:)
        type(string_t), allocatable, intent(out) :: node_cmps(:), sief_cmps(:), vari_cmps(:)
        type(status_t), intent(out) :: st
        logical :: want_node, want_sief, want_vari
        integer(i4) :: k, f
        character(len=:), allocatable :: name
        allocate (node_cmps(0), sief_cmps(0), vari_cmps(0))
        want_node = .false.
        want_sief = .false.
        want_vari = .false.
        do f = 1, size(fields)
            want_sief = want_sief .or. fields(f)%s == 'SIEF_ELGA'
            want_vari = want_vari .or. fields(f)%s == 'VARI_ELGA'
            want_node = want_node .or. .not. is_cell_field(fields(f)%s)
            if (is_cell_field(fields(f)%s) .and. size(res%spring_cell) == 0) then
                call set_error(st, STATUS_MODEL_ERROR, fields(f)%s // ' is not stored in ' // &
                    res%name // ': parasol stores it for the DIS_CHOC springs of ' // &
                    'STAT_NON_LINE only')
                return
            end if
        end do
        do k = 1, size(components)
            name = to_upper(components(k)%s)
            if (component_index(name) > 0 .and. want_node) then
                call push(node_cmps, name)
            else if (sief_component_index(name, res%spring_dim) > 0 .and. want_sief) then
                call push(sief_cmps, name)
            else if (vari_component_index(name, DIS_CHOC_N_VARI) > 0 .and. want_vari) then
                call push(vari_cmps, name)
            else
                call set_error(st, STATUS_MODEL_ERROR, components(k)%s // ' is no ' // &
                    'component of the fields asked for (NOM_CHAM ' // &
                    join_words(fields, ' ') // ')')
                return
            end if
        end do
        if (size(components) == 0) return
        if (want_node .and. size(node_cmps) == 0) call none_of('the node fields')
        if (want_sief .and. size(sief_cmps) == 0) call none_of('SIEF_ELGA')
        if (want_vari .and. size(vari_cmps) == 0) call none_of('VARI_ELGA')
    contains
        ! Appends one name (element by element: the array constructor
        ! [list, string_t(name)] leaked its temporary's component, valgrind).
        subroutine push(list, text)
            type(string_t), allocatable, intent(inout) :: list(:)
            character(len=*), intent(in) :: text
            type(string_t), allocatable :: bigger(:)
            integer :: m
            allocate (bigger(size(list) + 1))
            do m = 1, size(list)
                call move_alloc(list(m)%s, bigger(m)%s)
            end do
            bigger(size(bigger))%s = text
            call move_alloc(bigger, list)
        end subroutine push
        subroutine none_of(what)
            character(len=*), intent(in) :: what
            if (st%ok()) call set_error(st, STATUS_MODEL_ERROR, 'NOM_CMP names no ' // &
                'component of ' // what // ' (give one, or one IMPR_RESU occurrence per field)')
        end subroutine none_of
    end subroutine split_components

end module result_cell_arrays
