!> IMPR_RESU(FORMAT='VTK'): ParaView/VTK XML files from plain arrays (result_data).
!> One `.vtu` (UnstructuredGrid, ASCII, Float64) per instant with the node fields as point
!> data (expand_node_field: DEPL as a 3-component vector padded with zeros, ...), the cell
!> arrays as cell data (Float64, or Int32 for whole values; 0 on cells that do not carry
!> them), and a `.pvd`
!> collection listing the instants with their times. Every file is written atomically.
!> Format: "VTK File Formats", Kitware (XML UnstructuredGrid; cell types VTK_VERTEX = 1,
!> VTK_LINE = 3, VTK_TRIANGLE = 5, VTK_QUAD = 9; connectivity 0-based, offsets = end of each
!> cell).
module result_vtk
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_INTERNAL
    use strings, only: string_t, to_text
    use atomic_file, only: atomic_file_t, open_atomic
    use result_data, only: node_field_t, point_array_t, check_result_mesh, check_node_field, &
                           expand_node_field, cell_array_t, &
                           check_cell_array
    implicit none
    private

    !> 17 significant digits: values read back are bit-identical.
    character(len=*), parameter :: REAL_FORMAT = 'es24.16e3'

    public :: write_vtu_file, write_pvd_file, write_vtk_series, vtk_cell_type

contains

    !> VTK cell type of a RESULT_CELL_* code (0 if unknown).
    elemental integer function vtk_cell_type(cell_type)
        integer, intent(in) :: cell_type
        ! VTK_VERTEX, LINE, TRIANGLE, QUAD, QUADRATIC_EDGE, QUADRATIC_TRIANGLE,
        ! QUADRATIC_QUAD, BIQUADRATIC_QUAD (vtkCellType.h), in RESULT_CELL_* order
        integer, parameter :: CODES(8) = [1, 3, 5, 9, 21, 22, 23, 28]
        vtk_cell_type = 0
        if (cell_type >= 1 .and. cell_type <= size(CODES)) vtk_cell_type = CODES(cell_type)
    end function vtk_cell_type

    !> Writes one instant as a `.vtu` file.
    !>  path       : in, the file to write
    !>  coords, cell_types, cell_ptr, cell_nodes : in, the mesh (result_data conventions)
    !>  fields     : in, the node fields of the instant (may be empty)
    !>  st         : out, STATUS_INTERNAL for inconsistent arrays, STATUS_IO_ERROR when the
    !>               file cannot be written (then no file is left behind)
    !>  cell_arrays : in, optional, the cell arrays of the instant (<CellData>)
    subroutine write_vtu_file(path, coords, cell_types, cell_ptr, cell_nodes, fields, st, &
                              cell_arrays)
        character(len=*), intent(in) :: path
        real(dp), intent(in) :: coords(:, :)
        integer, intent(in) :: cell_types(:), cell_ptr(:), cell_nodes(:)
        type(node_field_t), intent(in) :: fields(:)
        type(status_t), intent(out) :: st
        type(cell_array_t), intent(in), optional :: cell_arrays(:)
        type(atomic_file_t) :: file
        integer :: f
        call check_result_mesh(coords, cell_types, cell_ptr, cell_nodes, st)
        if (st%failed()) return
        do f = 1, size(fields)
            call check_node_field(fields(f), size(coords, 2), st)
            if (st%failed()) return
        end do
        if (present(cell_arrays)) then
            do f = 1, size(cell_arrays)
                call check_cell_array(cell_arrays(f), size(cell_types), st)
                if (st%failed()) return
            end do
        end if
        call open_atomic(file, path, st)
        if (st%failed()) return
        call file%write_line('<?xml version="1.0"?>')
        call file%write_line('<VTKFile type="UnstructuredGrid" version="0.1" ' // &
                             'byte_order="LittleEndian" header_type="UInt64">')
        call file%write_line('  <UnstructuredGrid>')
        call file%write_line('    <Piece NumberOfPoints="' // to_text(size(coords, 2)) // &
                             '" NumberOfCells="' // to_text(size(cell_types)) // '">')
        call write_point_data(file, fields)
        if (present(cell_arrays)) call write_cell_data(file, cell_arrays)
        call file%write_line('      <Points>')
        call file%write_line('        <DataArray type="Float64" NumberOfComponents="3" ' // &
                             'format="ascii">')
        call write_real_rows(file, coords)
        call file%write_line('        </DataArray>')
        call file%write_line('      </Points>')
        call write_cells(file, cell_types, cell_ptr, cell_nodes)
        call file%write_line('    </Piece>')
        call file%write_line('  </UnstructuredGrid>')
        call file%write_line('</VTKFile>')
        call file%commit(st)
        if (st%failed()) call file%discard()
    end subroutine write_vtu_file

    !> <PointData> with one DataArray per expanded field array.
    subroutine write_point_data(file, fields)
        type(atomic_file_t), intent(in) :: file
        type(node_field_t), intent(in) :: fields(:)
        type(point_array_t), allocatable :: arrays(:)
        integer :: f, a
        call file%write_line('      <PointData>')
        do f = 1, size(fields)
            call expand_node_field(fields(f), arrays)
            do a = 1, size(arrays)
                call file%write_line('        <DataArray type="Float64" Name="' // &
                                     arrays(a)%name // '" NumberOfComponents="' // &
                                     to_text(size(arrays(a)%values, 1)) // '" format="ascii">')
                call write_real_rows(file, arrays(a)%values)
                call file%write_line('        </DataArray>')
            end do
        end do
        call file%write_line('      </PointData>')
    end subroutine write_point_data

    !> <CellData> with one scalar DataArray per cell array.
    subroutine write_cell_data(file, arrays)
        type(atomic_file_t), intent(in) :: file
        type(cell_array_t), intent(in) :: arrays(:)
        character(len=32) :: buf
        integer :: a, c
        if (size(arrays) == 0) return
        call file%write_line('      <CellData>')
        do a = 1, size(arrays)
            if (arrays(a)%whole) then
                call file%write_line('        <DataArray type="Int32" Name="' // &
                                     arrays(a)%name // '" format="ascii">')
                do c = 1, size(arrays(a)%values)
                    call file%write_line('          ' // to_text(nint(merge(arrays(a)%values(c), &
                        0.0_dp, arrays(a)%defined(c)))))
                end do
            else
                call file%write_line('        <DataArray type="Float64" Name="' // &
                                     arrays(a)%name // '" format="ascii">')
                do c = 1, size(arrays(a)%values)
                    write (buf, '(' // REAL_FORMAT // ')') merge(arrays(a)%values(c), 0.0_dp, &
                        arrays(a)%defined(c))
                    call file%write_line('          ' // trim(adjustl(buf)))
                end do
            end if
            call file%write_line('        </DataArray>')
        end do
        call file%write_line('      </CellData>')
    end subroutine write_cell_data

    !> <Cells>: connectivity (0-based), offsets (end of each cell), types.
    subroutine write_cells(file, cell_types, cell_ptr, cell_nodes)
        type(atomic_file_t), intent(in) :: file
        integer, intent(in) :: cell_types(:), cell_ptr(:), cell_nodes(:)
        character(len=64) :: buf
        integer :: c
        call file%write_line('      <Cells>')
        call file%write_line('        <DataArray type="Int64" Name="connectivity" ' // &
                             'format="ascii">')
        do c = 1, size(cell_types)
            write (buf, '(*(i0, :, " "))') cell_nodes(cell_ptr(c):cell_ptr(c + 1) - 1) - 1
            call file%write_line('          ' // trim(buf))
        end do
        call file%write_line('        </DataArray>')
        call file%write_line('        <DataArray type="Int64" Name="offsets" format="ascii">')
        do c = 1, size(cell_types)
            call file%write_line('          ' // to_text(cell_ptr(c + 1) - 1))
        end do
        call file%write_line('        </DataArray>')
        call file%write_line('        <DataArray type="UInt8" Name="types" format="ascii">')
        do c = 1, size(cell_types)
            call file%write_line('          ' // to_text(vtk_cell_type(cell_types(c))))
        end do
        call file%write_line('        </DataArray>')
        call file%write_line('      </Cells>')
    end subroutine write_cells

    !> One line per column of `values` (a point), 17 significant digits.
    subroutine write_real_rows(file, values)
        type(atomic_file_t), intent(in) :: file
        real(dp), intent(in) :: values(:, :)
        character(len=25 * 3 + 16) :: buf
        integer :: i
        do i = 1, size(values, 2)
            write (buf, '(*(' // REAL_FORMAT // ', :, " "))') values(:, i)
            call file%write_line('          ' // trim(adjustl(buf)))
        end do
    end subroutine write_real_rows

    !> Writes the `.pvd` collection of a series.
    !>  path      : in, the .pvd file
    !>  times     : in, (n_instants) the INST of each file
    !>  vtu_files : in, (n_instants) the .vtu names, relative to the .pvd's folder
    !>  st        : out, STATUS_IO_ERROR when the file cannot be written
    subroutine write_pvd_file(path, times, vtu_files, st)
        character(len=*), intent(in) :: path
        real(dp), intent(in) :: times(:)
        type(string_t), intent(in) :: vtu_files(:)
        type(status_t), intent(out) :: st
        type(atomic_file_t) :: file
        character(len=32) :: buf
        integer :: k
        call open_atomic(file, path, st)
        if (st%failed()) return
        call file%write_line('<?xml version="1.0"?>')
        call file%write_line('<VTKFile type="Collection" version="0.1" ' // &
                             'byte_order="LittleEndian">')
        call file%write_line('  <Collection>')
        do k = 1, min(size(times), size(vtu_files))
            write (buf, '(' // REAL_FORMAT // ')') times(k)
            call file%write_line('    <DataSet timestep="' // trim(adjustl(buf)) // &
                                 '" group="" part="0" file="' // vtu_files(k)%s // '"/>')
        end do
        call file%write_line('  </Collection>')
        call file%write_line('</VTKFile>')
        call file%commit(st)
        if (st%failed()) call file%discard()
    end subroutine write_pvd_file

    !> Writes a whole result: `<stem>_<k>.vtu` for instant k = 1..n (k with 4 digits at
    !> least) and `<stem>.pvd` listing them (names relative to the .pvd).
    !>  stem      : in, path without extension (e.g. out/ssnl130a_resu)
    !>  coords, cell_types, cell_ptr, cell_nodes : in, the mesh
    !>  times     : in, (n_instants) INST of each instant
    !>  fields    : in, (n_fields, n_instants) the node fields of each instant
    !>  st        : out, as write_vtu_file; stops at the first failure
    !>  cell_arrays : in, optional, (n_arrays, n_instants) the cell arrays of each instant
    subroutine write_vtk_series(stem, coords, cell_types, cell_ptr, cell_nodes, times, &
                                fields, st, cell_arrays)
        character(len=*), intent(in) :: stem
        real(dp), intent(in) :: coords(:, :)
        integer, intent(in) :: cell_types(:), cell_ptr(:), cell_nodes(:)
        real(dp), intent(in) :: times(:)
        type(node_field_t), intent(in) :: fields(:, :)
        type(status_t), intent(out) :: st
        type(cell_array_t), intent(in), optional :: cell_arrays(:, :)
        type(string_t) :: names(size(times))
        character(len=16) :: buf
        integer :: k
        if (size(fields, 2) /= size(times)) then
            call set_error(st, STATUS_INTERNAL, 'VTK series: fields must be ' // &
                           '(n_fields, n_instants) with one instant per time')
            return
        end if
        if (present(cell_arrays)) then
            if (size(cell_arrays, 2) /= size(times)) then
                call set_error(st, STATUS_INTERNAL, 'VTK series: cell arrays must be ' // &
                               '(n_arrays, n_instants) with one instant per time')
                return
            end if
        end if
        do k = 1, size(times)
            write (buf, '(i0.4)') k
            if (present(cell_arrays)) then
                call write_vtu_file(stem // '_' // trim(buf) // '.vtu', coords, cell_types, &
                                    cell_ptr, cell_nodes, fields(:, k), st, cell_arrays(:, k))
            else
                call write_vtu_file(stem // '_' // trim(buf) // '.vtu', coords, cell_types, &
                                    cell_ptr, cell_nodes, fields(:, k), st)
            end if
            if (st%failed()) return
            names(k)%s = base_name(stem) // '_' // trim(buf) // '.vtu'
        end do
        call write_pvd_file(stem // '.pvd', times, names, st)
    end subroutine write_vtk_series

    !> The file name part of a path (after the last '/').
    pure function base_name(path) result(name)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: name
        name = path(index(path, '/', back=.true.) + 1:)
    end function base_name


end module result_vtk
