!> Writes a tiny mesh with known fields as VTK (.vtu + .pvd) and Gmsh (.msh) into the folder
!> given as first argument; check_result_files.py reads them back with meshio.
!> Mesh: QUAD4 (1 2 3 4), TRIA3 (2 5 3), SEG2 (4 6), POI1 (6); node i at (i, 2i, 3i)/10.
!> Fields at INST t = 0.5, 1.0: DEPL (DX DY DZ DRZ), value t*(10*node + component), node 5
!> without DZ, node 6 without DRZ; REAC_NODA (DX DY) = -DEPL.
program write_result_files
    use kinds, only: dp
    use status, only: status_t, format_status
    use strings, only: string_t
    use result_data, only: node_field_t, RESULT_CELL_POI1, RESULT_CELL_SEG2, &
                           RESULT_CELL_TRIA3, RESULT_CELL_QUAD4
    use result_vtk, only: write_vtk_series
    use result_gmsh, only: write_gmsh_file
    implicit none
    integer, parameter :: nn = 6
    real(dp) :: coords(3, nn), times(2)
    integer :: cell_types(4), cell_ptr(5), cell_nodes(10), i, k, c
    type(node_field_t) :: fields(2, 2)
    type(status_t) :: st
    character(len=512) :: dir
    call get_command_argument(1, dir)
    do i = 1, nn
        coords(:, i) = [1.0_dp, 2.0_dp, 3.0_dp] * real(i, dp) / 10.0_dp
    end do
    cell_types = [RESULT_CELL_QUAD4, RESULT_CELL_TRIA3, RESULT_CELL_SEG2, RESULT_CELL_POI1]
    cell_ptr = [1, 5, 8, 10, 11]
    cell_nodes = [1, 2, 3, 4, 2, 5, 3, 4, 6, 6]
    times = [0.5_dp, 1.0_dp]
    do k = 1, 2
        fields(1, k)%name = 'DEPL'
        fields(1, k)%components = [string_t('DX'), string_t('DY'), string_t('DZ'), string_t('DRZ')]
        allocate (fields(1, k)%values(4, nn), fields(1, k)%mask(4, nn))
        do i = 1, nn
            do c = 1, 4
                fields(1, k)%values(c, i) = times(k) * real(10 * i + c, dp)
            end do
        end do
        fields(1, k)%mask = .true.
        fields(1, k)%mask(3, 5) = .false.
        fields(1, k)%mask(4, 6) = .false.
        fields(2, k)%name = 'REAC_NODA'
        fields(2, k)%components = [string_t('DX'), string_t('DY')]
        fields(2, k)%values = -fields(1, k)%values(1:2, :)
        fields(2, k)%mask = fields(1, k)%mask(1:2, :)
    end do
    call write_vtk_series(trim(dir) // '/tiny', coords, cell_types, cell_ptr, cell_nodes, &
                          times, fields, st)
    if (st%ok()) call write_gmsh_file(trim(dir) // '/tiny.msh', coords, cell_types, cell_ptr, &
                                      cell_nodes, times, [1, 2], fields, st)
    if (st%failed()) then
        write (*, '(a)') format_status(st)
        error stop 1
    end if
end program write_result_files
