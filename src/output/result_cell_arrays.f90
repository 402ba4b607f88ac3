!> Cell data IMPR_RESU writes for viewers (VTK CellData, Gmsh $ElementData) besides the
!> element fields (field_viewer_data):
!>  - SPRING_STATUS, with the element fields of a result with DIS_CHOC springs: 1 closed
!>    (in contact), 2 open, carried by the springs (VTK writes 0 on the other cells, so
!>    that colouring by it shows the open and the closed springs and the rest of the mesh
!>    apart at once);
!>  - GROUP_<name> for every cell group of the mesh: 1 on its cells (the group of each cell,
!>    to threshold or colour by in a viewer).
module result_cell_arrays
    use kinds, only: dp, i4
    use mesh_types, only: mesh_t, n_cell_groups, cell_group_name, cells_of_group
    use analysis_result, only: result_concept_t
    use result_data, only: cell_array_t
    implicit none
    private

    !> SPRING_STATUS values.
    real(dp), parameter, public :: SPRING_STATUS_CLOSED = 1.0_dp, SPRING_STATUS_OPEN = 2.0_dp

    public :: spring_status_array, group_cell_arrays

contains

    !> SPRING_STATUS at stored instant `stored` (1..n_stored) of an analysis result.
    subroutine spring_status_array(res, stored, array)
        type(result_concept_t), intent(in) :: res
        integer(i4), intent(in) :: stored
        type(cell_array_t), intent(out) :: array
        integer(i4) :: k
        array%name = 'SPRING_STATUS'
        array%whole = .true.
        allocate (array%values(res%mesh%n_cells), source=0.0_dp)
        allocate (array%defined(res%mesh%n_cells), source=.false.)
        if (stored < 1 .or. stored > res%n_stored) return
        do k = 1, size(res%spring_cell)
            array%defined(res%spring_cell(k)) = .true.
            array%values(res%spring_cell(k)) = merge(SPRING_STATUS_CLOSED, &
                SPRING_STATUS_OPEN, res%spring_closed(k, stored))
        end do
    end subroutine spring_status_array

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

end module result_cell_arrays
