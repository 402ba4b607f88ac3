!> IMPR_RESU(FORMAT='GMSH'): a Gmsh `.msh` file, format 2.2 ASCII, from plain arrays
!> (result_data): $MeshFormat, $Nodes, $Elements (Gmsh types 15 = point, 1 = 2-node line,
!> 2 = 3-node triangle, 3 = 4-node quadrangle; two tags: physical 0, elementary 1), one
!> $NodeData block per field array per instant (string tag: the view name; real tag: the
!> time; integer tags: time step, number of components (1 or 3), number of nodes) and one
!> $ElementData block per cell array per instant, every cell listed, 0 on the cells that do
!> not carry the array (as in VTK). A view's name is the array's followed by the instant,
!> `DEPL (INST 1.5E+00)`, so that Gmsh's view list and title say which instant is shown; an
!> array that does not change (a cell group) is written once, named without instant.
!> Format: Gmsh reference manual, "MSH file format version 2 (legacy)". Written atomically.
module result_gmsh
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_INTERNAL
    use atomic_file, only: atomic_file_t, open_atomic
    use result_data, only: node_field_t, point_array_t, check_result_mesh, check_node_field, &
                           expand_node_field, cell_array_t, &
                           check_cell_array
    use strings, only: to_text
    implicit none
    private

    !> 17 significant digits: values read back are bit-identical.
    character(len=*), parameter :: REAL_FORMAT = 'es24.16e3'

    public :: write_gmsh_file, gmsh_element_type, gmsh_view_name

contains

    !> Gmsh element type of a RESULT_CELL_* code (0 if unknown).
    elemental integer function gmsh_element_type(cell_type)
        integer, intent(in) :: cell_type
        ! point, line, triangle, quadrangle, 3-node line, 6-node triangle, 8-node and
        ! 9-node quadrangles (Gmsh's MSH element types), in RESULT_CELL_* order
        integer, parameter :: CODES(8) = [15, 1, 2, 3, 8, 9, 16, 10]
        gmsh_element_type = 0
        if (cell_type >= 1 .and. cell_type <= size(CODES)) gmsh_element_type = CODES(cell_type)
    end function gmsh_element_type

    !> Writes the mesh and every field of every instant to one `.msh` file.
    !>  path       : in, the file to write
    !>  coords, cell_types, cell_ptr, cell_nodes : in, the mesh (result_data conventions)
    !>  times      : in, (n_instants) INST of each instant
    !>  steps      : in, (n_instants) the time-step tag of each instant (e.g. NUME_ORDRE)
    !>  fields     : in, (n_fields, n_instants) the node fields (n_instants may be 0)
    !>  st         : out, STATUS_INTERNAL for inconsistent arrays, STATUS_IO_ERROR when the
    !>               file cannot be written (then no file is left behind)
    !>  cell_arrays : in, optional, (n_arrays, n_instants) the cell arrays of each instant
    subroutine write_gmsh_file(path, coords, cell_types, cell_ptr, cell_nodes, times, steps, &
                               fields, st, cell_arrays)
        character(len=*), intent(in) :: path
        real(dp), intent(in) :: coords(:, :)
        integer, intent(in) :: cell_types(:), cell_ptr(:), cell_nodes(:)
        real(dp), intent(in) :: times(:)
        integer, intent(in) :: steps(:)
        type(node_field_t), intent(in) :: fields(:, :)
        type(status_t), intent(out) :: st
        type(cell_array_t), intent(in), optional :: cell_arrays(:, :)
        type(atomic_file_t) :: file
        type(point_array_t), allocatable :: arrays(:)
        integer :: f, k, a
        call check_result_mesh(coords, cell_types, cell_ptr, cell_nodes, st)
        if (st%failed()) return
        if (size(fields, 2) /= size(times) .or. size(steps) /= size(times)) then
            call set_error(st, STATUS_INTERNAL, 'Gmsh output: fields must be (n_fields, ' // &
                           'n_instants) with one time and one step per instant')
            return
        end if
        do k = 1, size(fields, 2)
            do f = 1, size(fields, 1)
                call check_node_field(fields(f, k), size(coords, 2), st)
                if (st%failed()) return
            end do
        end do
        if (present(cell_arrays)) then
            if (size(cell_arrays, 2) /= size(times)) then
                call set_error(st, STATUS_INTERNAL, 'Gmsh output: cell arrays must be ' // &
                               '(n_arrays, n_instants)')
                return
            end if
            do k = 1, size(cell_arrays, 2)
                do f = 1, size(cell_arrays, 1)
                    call check_cell_array(cell_arrays(f, k), size(cell_types), st)
                    if (st%failed()) return
                end do
            end do
        end if
        call open_atomic(file, path, st)
        if (st%failed()) return
        call file%write_line('$MeshFormat')
        call file%write_line('2.2 0 8')
        call file%write_line('$EndMeshFormat')
        call write_nodes(file, coords)
        call write_elements(file, cell_types, cell_ptr, cell_nodes)
        do k = 1, size(fields, 2)
            do f = 1, size(fields, 1)
                call expand_node_field(fields(f, k), arrays)
                do a = 1, size(arrays)
                    call write_node_data(file, arrays(a), times(k), steps(k))
                end do
            end do
            if (.not. present(cell_arrays)) cycle
            do f = 1, size(cell_arrays, 1)
                if (cell_arrays(f, k)%constant .and. k > 1) cycle    ! once, at the first
                call write_element_data(file, cell_arrays(f, k), times(k), steps(k))
            end do
        end do
        call file%commit(st)
        if (st%failed()) call file%discard()
    end subroutine write_gmsh_file

    !> $Nodes: count, then `number x y z` per node.
    subroutine write_nodes(file, coords)
        type(atomic_file_t), intent(in) :: file
        real(dp), intent(in) :: coords(:, :)
        character(len=128) :: buf
        integer :: i
        call file%write_line('$Nodes')
        call file%write_line(to_text(size(coords, 2)))
        do i = 1, size(coords, 2)
            write (buf, '(i0, 3(" ", ' // REAL_FORMAT // '))') i, coords(:, i)
            call file%write_line(squeeze(buf))
        end do
        call file%write_line('$EndNodes')
    end subroutine write_nodes

    !> $Elements: count, then `number type 2 0 1 nodes...` per cell.
    subroutine write_elements(file, cell_types, cell_ptr, cell_nodes)
        type(atomic_file_t), intent(in) :: file
        integer, intent(in) :: cell_types(:), cell_ptr(:), cell_nodes(:)
        character(len=128) :: buf
        integer :: c
        call file%write_line('$Elements')
        call file%write_line(to_text(size(cell_types)))
        do c = 1, size(cell_types)
            write (buf, '(*(i0, :, " "))') c, gmsh_element_type(cell_types(c)), 2, 0, 1, &
                cell_nodes(cell_ptr(c):cell_ptr(c + 1) - 1)
            call file%write_line(trim(buf))
        end do
        call file%write_line('$EndElements')
    end subroutine write_elements

    !> The opening of a $NodeData / $ElementData block: `$<kind>`, one string tag (the view
    !> name), one real tag (the time), three integer tags (step, components, entries).
    subroutine write_data_header(file, kind, view, time, step, components, entries)
        type(atomic_file_t), intent(in) :: file
        character(len=*), intent(in) :: kind, view
        real(dp), intent(in) :: time
        integer, intent(in) :: step, components, entries
        character(len=32) :: buf
        call file%write_line('$' // kind)
        call file%write_line('1')
        call file%write_line('"' // view // '"')
        call file%write_line('1')
        write (buf, '(' // REAL_FORMAT // ')') time
        call file%write_line(trim(adjustl(buf)))
        call file%write_line('3')
        call file%write_line(to_text(step))
        call file%write_line(to_text(components))
        call file%write_line(to_text(entries))
    end subroutine write_data_header

    !> One $NodeData block.
    subroutine write_node_data(file, array, time, step)
        type(atomic_file_t), intent(in) :: file
        type(point_array_t), intent(in) :: array
        real(dp), intent(in) :: time
        integer, intent(in) :: step
        character(len=128) :: buf
        integer :: i
        call write_data_header(file, 'NodeData', gmsh_view_name(array%name, time), time, step, &
            size(array%values, 1), size(array%values, 2))
        do i = 1, size(array%values, 2)
            write (buf, '(i0, *(" ", ' // REAL_FORMAT // '))') i, array%values(:, i)
            call file%write_line(squeeze(buf))
        end do
        call file%write_line('$EndNodeData')
    end subroutine write_node_data

    !> One $ElementData block: `number value` for every cell (0 where the array is not
    !> defined).
    subroutine write_element_data(file, array, time, step)
        type(atomic_file_t), intent(in) :: file
        type(cell_array_t), intent(in) :: array
        real(dp), intent(in) :: time
        integer, intent(in) :: step
        character(len=128) :: buf
        integer :: c
        if (array%constant) then
            call write_data_header(file, 'ElementData', array%name, time, step, 1, &
                size(array%values))
        else
            call write_data_header(file, 'ElementData', gmsh_view_name(array%name, time), &
                time, step, 1, size(array%values))
        end if
        do c = 1, size(array%values)
            write (buf, '(i0, " ", ' // REAL_FORMAT // ')') c, merge(array%values(c), 0.0_dp, &
                array%defined(c))
            call file%write_line(squeeze(buf))
        end do
        call file%write_line('$EndElementData')
    end subroutine write_element_data

    !> The name of a Gmsh view: `NAME (INST t)` with t in at most 7 significant digits
    !> (trailing zeros dropped), e.g. `DEPL (INST 1.5E+00)`.
    pure function gmsh_view_name(name, time) result(view)
        character(len=*), intent(in) :: name
        real(dp), intent(in) :: time
        character(len=:), allocatable :: view, mantissa
        character(len=24) :: buf
        integer :: e
        write (buf, '(es14.6e2)') time
        buf = adjustl(buf)
        e = index(buf, 'E')
        mantissa = buf(1:e - 1)
        do while (len(mantissa) > 3 .and. mantissa(len(mantissa):) == '0')
            if (mantissa(len(mantissa) - 1:len(mantissa) - 1) == '.') exit
            mantissa = mantissa(1:len(mantissa) - 1)
        end do
        view = name // ' (INST ' // mantissa // trim(buf(e:)) // ')'
    end function gmsh_view_name

    !> `text` with runs of blanks reduced to one and no leading or trailing blanks.
    pure function squeeze(text) result(out)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: out
        character(len=len(text)) :: buf
        integer :: i, n
        n = 0
        do i = 1, len_trim(text)
            if (text(i:i) == ' ') then
                if (n == 0) cycle
                if (buf(n:n) == ' ') cycle
            end if
            n = n + 1
            buf(n:n) = text(i:i)
        end do
        out = buf(1:n)
    end function squeeze


end module result_gmsh
