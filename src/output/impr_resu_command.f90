!> IMPR_RESU: prints meshes and fields (doc/listings.md, "IMPR_RESU"). Each RESU occurrence
!> names what it prints (impr_resu_select: RESULTAT with NOM_CHAM at its instants, CHAM_GD,
!> MAILLAGE; NOM_CMP, GROUP_NO, GROUP_MA), and the fields are those TEST_RESU reads
!> (result_access), at the nodes or the cells' points:
!>  FORMAT='RESULTAT' (parasol's default): tables in the `.resu`, one per field and instant
!>                    (field_listing); MAILLAGE alone: the mesh in Code_Aster's ASTER format;
!>  FORMAT='VTK'      : per RESU occurrence `<stem>_<NAME>.pvd` and one
!>                    `<stem>_<NAME>_NNNN.vtu` per instant in the output folder;
!>  FORMAT='GMSH'     : per RESU occurrence `<stem>_<NAME>.msh` in the output folder;
!>  FORMAT='MED'      : the mesh and the fields (result_med, laid out as Code_Aster writes
!>                    them) in the file bound to UNITE (default 80, as Code_Aster) with
!>                    `--unit 80=PATH`, every RESU occurrence in that one file; unbound, one
!>                    `<stem>_<NAME>.rmed` per occurrence in the output folder. A file
!>                    written earlier in the run is added to (Code_Aster adds to the file
!>                    of a unit), not replaced; the mesh goes in once.
!> For VTK and GMSH, a UNITE given in the deck and bound with `--unit N=PATH` replaces the
!> default name: PATH itself for GMSH; for VTK the .pvd is PATH (`.pvd` added when PATH lacks
!> it) and the .vtu files are named after it. Files are named in the .mess.
!>
!> Viewers get node fields as point data and cell fields as cell data (field_viewer_data:
!> the mean of each cell's points, per component and sub-point), every cell group as
!> GROUP_<name> and, with the element fields of a result with DIS_CHOC springs,
!> SPRING_STATUS. A value that is not a finite number is never written: the command stops
!> with an error naming the field, and the node or cell.
module impr_resu_command
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_INTERNAL
    use strings, only: string_t, to_text, ends_with, real_e13
    use deck_concept, only: concept_t
    use deck_value, only: append_string
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, node_name, cell_name, CELL_TYPE_NAMES
    use field_types, only: field_t, FIELD_NOEU, field_type_cham
    use analysis_result, only: result_concept_t
    use result_data, only: node_field_t, cell_array_t, cell_type_from_name
    use result_cell_arrays, only: group_cell_arrays, spring_status_array
    use result_vtk, only: write_vtk_series
    use result_gmsh, only: write_gmsh_file
    use result_med, only: med_output_t, med_output_open, med_output_commit, &
        med_output_discard, med_output_mesh, write_med_mesh, write_med_node_field, &
        med_field_name, write_med_cell_field, med_cell_step_t
    use impr_resu_select, only: print_set_t, print_item_t, select_occurrence, locate
    use field_listing, only: field_table_lines
    use field_viewer_data, only: node_field_of, cell_arrays_of, field_columns
    use mesh_listing, only: aster_mesh_lines
    use unit_text_output, only: write_unit_text
    implicit none
    private

    !> Code_Aster's default UNITE of IMPR_RESU for FORMAT='MED' (U4.91.01).
    integer(i4), parameter :: MED_DEFAULT_UNIT = 80

    public :: run_impr_resu, result_mesh_arrays

contains

    !> Handler of IMPR_RESU (doc/architecture.md "Writing a command handler").
    !>  st : located errors (impr_resu_select's, a bound UNITE with several RESU, a
    !>       non-finite value), STATUS_IO_ERROR when a file cannot be written
    subroutine run_impr_resu(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: format, bound_path
        type(print_set_t) :: set
        integer :: k
        if (allocated(result)) deallocate (result)     ! IMPR_RESU has no result
        call cmd%get_text('FORMAT', format, st)
        if (st%failed()) return
        if (format == 'MED') then
            call print_med(ctx, cmd, st)
            return
        end if
        call bound_unit_path(ctx, cmd, bound_path, st)
        if (st%failed()) return
        do k = 1, cmd%count('RESU')
            call select_occurrence(cmd%occurrence('RESU', k), set, st)
            if (st%ok()) call check_finite(cmd%occurrence('RESU', k), set, st)
            if (st%failed()) return
            select case (format)
            case ('VTK', 'GMSH')
                call write_viewer_file(ctx, format, bound_path, set, st)
            case default
                call write_tables(ctx, cmd, set, st)
            end select
            if (st%failed()) return
        end do
    end subroutine run_impr_resu

    !> The path of UNITE when the deck gives it and `--unit` binds it ('' otherwise); a bound
    !> unit holds one result, so then only one RESU occurrence is allowed (VTK, GMSH).
    subroutine bound_unit_path(ctx, cmd, path, st)
        type(run_context_t), intent(in) :: ctx
        type(command_t), intent(in) :: cmd
        character(len=:), allocatable, intent(out) :: path
        type(status_t), intent(out) :: st
        integer(i4) :: unit
        character(len=:), allocatable :: format
        path = ''
        call cmd%get_text('FORMAT', format, st)
        if (st%failed()) return
        if (format == 'RESULTAT' .or. .not. cmd%given('UNITE')) return
        call cmd%get_int('UNITE', unit, st)
        if (st%failed()) return
        if (.not. any(ctx%unit_numbers == unit)) return
        call ctx%unit_path(unit, format, path, st)
        if (st%failed()) return
        if (cmd%count('RESU') > 1) call cmd%error_at('UNITE', 'unit ' // to_text(unit) // &
            ' is bound to one file, which holds one result: give one RESU occurrence ' // &
            'per IMPR_RESU (or leave the unit unbound for one file per result)', st)
    end subroutine bound_unit_path

    !> Refuses a value that is not a finite number (named with its node or cell).
    subroutine check_finite(occ, set, st)
        type(keyword_set_t), intent(in) :: occ
        type(print_set_t), intent(in) :: set
        type(status_t), intent(out) :: st
        integer(i4) :: k, j, n, c
        integer(i8) :: v
        do k = 1, size(set%items)
            associate (f => set%items(k)%f)
                if (f%location == FIELD_NOEU) then
                    do n = 1, f%n_nodes
                        do j = 1, size(f%components, kind=i4)
                            if (.not. f%node_has(j, n)) cycle
                            if (ieee_is_finite(f%node_values(j, n))) cycle
                            call occ%error_at(trim(merge('NOM_CHAM', 'CHAM_GD ', &
                                set%from_result)), set%items(k)%name // ' at node ' // &
                                node_name(set%mesh, n) // ', component ' // &
                                f%components(j)%s // ' is not a finite number; not written', &
                                st, STATUS_MODEL_ERROR)
                            return
                        end do
                    end do
                else
                    if (all(ieee_is_finite(f%values))) cycle
                    do c = 1, f%n_cells
                        do v = f%offset(c) + 1, f%offset(c + 1)
                            if (ieee_is_finite(f%values(v))) cycle
                            call occ%error_at(trim(merge('NOM_CHAM', 'CHAM_GD ', &
                                set%from_result)), set%items(k)%name // ' on cell ' // &
                                cell_name(set%mesh, c) // ' has a value that is not a ' // &
                                'finite number; not written', st, STATUS_MODEL_ERROR)
                            return
                        end do
                    end do
                end if
            end associate
        end do
    end subroutine check_finite

    !> FORMAT='RESULTAT': one table per field and instant in the listing of UNITE (8, the
    !> .resu, by default; another unit goes to its file as IMPR_TABLE's do:
    !> unit_text_output); a mesh alone in Code_Aster's ASTER format.
    !>  st : STATUS_IO_ERROR located at UNITE when its file cannot be written
    subroutine write_tables(ctx, cmd, set, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(print_set_t), intent(in) :: set
        type(status_t), intent(out) :: st
        type :: table_lines_t
            type(string_t), allocatable :: lines(:)
        end type table_lines_t
        type(table_lines_t), allocatable :: tables(:)
        type(string_t), allocatable :: all_lines(:)
        character(len=:), allocatable :: what, where
        integer :: k, i, n
        integer(i4) :: unit
        call cmd%get_int('UNITE', unit, st)
        if (st%failed()) return
        if (set%mesh_only) then
            call aster_mesh_lines(set%mesh, all_lines)
            what = 'the mesh (' // to_text(set%mesh%n_nodes) // ' nodes, ' // &
                to_text(set%mesh%n_cells) // ' cells)'
        else
            ! each table built once, then its lines moved (not copied) into one listing:
            ! no array constructor of string_t (gfortran 12 leaks its temporaries, and
            ! growing by [all, lines] copies every line again per table)
            allocate (tables(size(set%items)))
            do k = 1, size(set%items)
                call field_table_lines(set, set%items(k), tables(k)%lines)
            end do
            allocate (all_lines(sum([(size(tables(k)%lines), k = 1, size(tables))])))
            n = 0
            do k = 1, size(tables)
                do i = 1, size(tables(k)%lines)
                    call move_alloc(tables(k)%lines(i)%s, all_lines(n + i)%s)
                end do
                n = n + size(tables(k)%lines)
            end do
            what = to_text(size(set%items, kind=i4)) // ' table(s) of ' // set%owner
        end if
        call write_unit_text(ctx, unit, all_lines, where, st, cmd, 'UNITE')
        if (st%ok()) call ctx%write_mess('    IMPR_RESU: ' // what // ' written to ' // where)
    end subroutine write_tables

    !> FORMAT='VTK' or 'GMSH': the mesh with every field of every instant: node fields as
    !> point data, cell fields and the cell groups as cell data.
    subroutine write_viewer_file(ctx, format, bound_path, set, st)
        type(run_context_t), intent(inout) :: ctx
        character(len=*), intent(in) :: format, bound_path
        type(print_set_t), intent(in) :: set
        type(status_t), intent(out) :: st
        type(node_field_t), allocatable :: node_fields(:, :)
        type(cell_array_t), allocatable :: cells(:, :)
        integer, allocatable :: cell_types(:), cell_ptr(:), cell_nodes(:), steps(:)
        real(dp), allocatable :: times(:)
        character(len=:), allocatable :: path, name
        call result_mesh_arrays(set%mesh, cell_types, cell_ptr, cell_nodes, st)
        if (st%failed()) return
        call viewer_data(set, times, steps, node_fields, cells)
        name = set%owner
        if (len(name) == 0) name = 'MAIL'
        if (format == 'VTK') then
            path = bound_path
            if (len(path) == 0) path = ctx%output_path('_' // name // '.pvd')
            if (.not. ends_with(path, '.pvd')) path = path // '.pvd'
            call write_vtk_series(path(1:len(path) - 4), set%mesh%coords, cell_types, &
                cell_ptr, cell_nodes, times, node_fields, st, cells)
            if (st%ok()) call ctx%write_mess('    IMPR_RESU: wrote ' // path // ' and ' // &
                to_text(size(times)) // ' .vtu file(s) next to it')
        else
            path = bound_path
            if (len(path) == 0) path = ctx%output_path('_' // name // '.msh')
            call write_gmsh_file(path, set%mesh%coords, cell_types, cell_ptr, cell_nodes, &
                times, steps, node_fields, st, cells)
            if (st%ok()) call ctx%write_mess('    IMPR_RESU: wrote ' // path)
        end if
    end subroutine write_viewer_file

    !> The instants of a print set (in the order first met; one at INST 0 for a CHAM_GD or a
    !> mesh) and, per instant, its node fields and cell arrays, the same arrays at every
    !> instant (an array an instant lacks is defined nowhere there).
    subroutine viewer_data(set, times, steps, node_fields, cells)
        type(print_set_t), intent(in) :: set
        real(dp), allocatable, intent(out) :: times(:)
        integer, allocatable, intent(out) :: steps(:)
        type(node_field_t), allocatable, intent(out) :: node_fields(:, :)
        type(cell_array_t), allocatable, intent(out) :: cells(:, :)
        type(cell_array_t), allocatable :: groups(:), some(:), status_array(:)
        type(string_t), allocatable :: node_names(:), cell_names(:)
        integer, allocatable :: at(:), stored(:)
        integer :: k, j, n, a
        logical :: any_cell_field
        ! the instants
        allocate (times(0), steps(0), stored(0), at(size(set%items)))
        do k = 1, size(set%items)
            n = 0
            do j = 1, size(stored)
                if (stored(j) == set%items(k)%at) n = j
            end do
            if (n == 0) then
                times = [times, set%items(k)%inst]
                steps = [steps, int(set%items(k)%nume_ordre)]
                stored = [stored, int(set%items(k)%at)]
                n = size(steps)
            end if
            at(k) = n
        end do
        if (size(times) == 0) then
            times = [0.0_dp]
            steps = [0]
            stored = [0]
        end if
        ! the node fields: one row per field name
        allocate (node_names(0), cell_names(0))
        any_cell_field = .false.
        do k = 1, size(set%items)
            if (set%items(k)%f%location == FIELD_NOEU) then
                if (.not. listed(node_names, set%items(k)%name)) &
                    call append_string(node_names, set%items(k)%name)
            else
                any_cell_field = .true.
            end if
        end do
        allocate (node_fields(size(node_names), size(times)))
        do k = 1, size(set%items)
            if (set%items(k)%f%location /= FIELD_NOEU) cycle
            j = position(node_names, set%items(k)%name)
            call node_field_of(set%items(k)%f, set%items(k)%name, set%components, &
                node_fields(j, at(k)))
        end do
        do j = 1, size(node_names)          ! a field an instant lacks: carried nowhere
            do k = 1, size(times)
                if (allocated(node_fields(j, k)%values)) cycle
                call empty_like(node_fields(j, :), node_fields(j, k))
            end do
        end do
        ! the cell arrays: the groups, the element fields, SPRING_STATUS
        call group_cell_arrays(set%mesh, groups)
        allocate (some(0))
        do k = 1, size(set%items)                 ! every array name, in order
            if (set%items(k)%f%location == FIELD_NOEU) cycle
            call cell_arrays_of(set%items(k)%f, set%items(k)%name, set%components, &
                set%cell_taken, some)
            do a = 1, size(some)
                if (.not. listed(cell_names, some(a)%name)) &
                    call append_string(cell_names, some(a)%name)
            end do
        end do
        allocate (status_array(0))
        allocate (cells(size(groups) + size(cell_names) + 1, size(times)))
        n = size(groups) + size(cell_names)
        do j = 1, size(times)
            cells(1:size(groups), j) = groups
        end do
        do k = 1, size(set%items)
            if (set%items(k)%f%location == FIELD_NOEU) cycle
            call cell_arrays_of(set%items(k)%f, set%items(k)%name, set%components, &
                set%cell_taken, some)
            do a = 1, size(some)
                cells(size(groups) + position(cell_names, some(a)%name), at(k)) = some(a)
            end do
        end do
        do j = 1, size(times)
            do a = size(groups) + 1, n
                if (allocated(cells(a, j)%values)) cycle
                cells(a, j)%name = cell_names(a - size(groups))%s
                allocate (cells(a, j)%values(set%mesh%n_cells), source=0.0_dp)
                allocate (cells(a, j)%defined(set%mesh%n_cells), source=.false.)
            end do
        end do
        ! SPRING_STATUS with the element fields of a result with DIS_CHOC springs
        if (any_cell_field .and. with_springs(set)) then
            do j = 1, size(times)
                call spring_status_array(spring_result(set), int(stored(j), i4), &
                    cells(n + 1, j))
            end do
        else
            cells = cells(1:n, :)
        end if
    contains
        logical function listed(names, name)
            type(string_t), intent(in) :: names(:)
            character(len=*), intent(in) :: name
            listed = position(names, name) > 0
        end function listed
        integer function position(names, name)
            type(string_t), intent(in) :: names(:)
            character(len=*), intent(in) :: name
            integer :: i
            position = 0
            do i = 1, size(names)
                if (names(i)%s == name) position = i
            end do
        end function position
    end subroutine viewer_data

    ! A node field carried nowhere, with the name and components of one of `row`.
    subroutine empty_like(row, out)
        type(node_field_t), intent(in) :: row(:)
        type(node_field_t), intent(out) :: out
        integer :: k
        do k = 1, size(row)
            if (.not. allocated(row(k)%values)) cycle
            out%name = row(k)%name
            out%components = row(k)%components
            allocate (out%values(size(row(k)%values, 1), size(row(k)%values, 2)), &
                source=0.0_dp)
            allocate (out%mask(size(row(k)%values, 1), size(row(k)%values, 2)), &
                source=.false.)
            return
        end do
    end subroutine empty_like

    ! True when the print set is of an analysis result with DIS_CHOC springs.
    logical function with_springs(set)
        type(print_set_t), intent(in) :: set
        type(result_concept_t), pointer :: res
        with_springs = .false.
        res => spring_result(set)
        if (.not. associated(res)) return
        with_springs = size(res%spring_cell) > 0
    end function with_springs

    ! The analysis result a print set's fields come from, if it has springs' status.
    function spring_result(set) result(res)
        type(print_set_t), intent(in) :: set
        type(result_concept_t), pointer :: res
        res => null()
        if (.not. associated(set%result)) return
        select type (r => set%result)
        type is (result_concept_t)
            if (allocated(r%spring_cell)) res => r
        end select
    end function spring_result

    !> FORMAT='MED': every RESU occurrence into the file of UNITE (default 80) when it is
    !> bound, else into one <stem>_<NAME>.rmed per occurrence.
    subroutine print_med(ctx, cmd, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: bound_path
        integer(i4) :: unit
        integer :: k
        unit = MED_DEFAULT_UNIT
        if (cmd%given('UNITE')) then
            call cmd%get_int('UNITE', unit, st)
            if (st%failed()) return
        end if
        bound_path = ''
        if (any(ctx%unit_numbers == unit)) then
            call ctx%unit_path(unit, 'MED', bound_path, st)
            if (st%failed()) return
        end if
        do k = 1, cmd%count('RESU')
            call print_med_occurrence(ctx, bound_path, cmd%occurrence('RESU', k), st)
            if (st%failed()) return
        end do
    end subroutine print_med

    !> One RESU occurrence into a MED file: the mesh (once per file) and each field, one
    !> computation step per instant (a CHAM_GD: one step, numbers -1, time 0).
    subroutine print_med_occurrence(ctx, bound_path, occ, st)
        type(run_context_t), intent(inout) :: ctx
        character(len=*), intent(in) :: bound_path
        type(keyword_set_t), intent(in) :: occ
        type(status_t), intent(out) :: st
        type(print_set_t) :: set
        type(med_output_t) :: out
        character(len=:), allocatable :: path, mesh_name, written, field_name, name
        logical :: append, exists
        integer :: first, last
        call select_occurrence(occ, set, st)
        if (st%ok()) call check_finite(occ, set, st)
        if (st%failed()) return
        name = set%owner
        if (len(name) == 0) name = mesh_stem(set%mesh%file)
        path = bound_path
        if (len(path) == 0) path = ctx%output_path('_' // name // '.rmed')
        append = .false.
        if (allocated(ctx%result_files)) append = any_path(ctx%result_files, path)
        call med_output_open(out, path, append, st)
        if (st%failed()) return
        call med_output_mesh(out, set%mesh, mesh_stem(set%mesh%file), mesh_name, exists, st)
        if (st%ok() .and. .not. exists) call write_med_mesh(out, set%mesh, mesh_name, st)
        written = ''
        first = 1
        do while (first <= size(set%items) .and. st%ok())
            last = first
            do while (last < size(set%items))
                if (set%items(last + 1)%name /= set%items(first)%name) exit
                last = last + 1
            end do
            field_name = set%items(first)%name
            if (set%from_result) field_name = med_field_name(set%owner, set%items(first)%name)
            if (set%items(first)%f%location == FIELD_NOEU) then
                call write_node_steps(out, set, first, last, mesh_name, field_name, st)
            else
                call write_cell_steps(out, set, first, last, mesh_name, field_name, st)
            end if
            if (st%failed()) then
                call locate(occ, trim(merge('NOM_CHAM', 'CHAM_GD ', set%from_result)), st)
                exit
            end if
            if (len(written) > 0) written = written // ', '
            written = written // field_name
            first = last + 1
        end do
        if (st%failed()) then
            call med_output_discard(out)
            return
        end if
        call med_output_commit(out, st)
        if (st%failed()) return
        call note_result_file(ctx, path)
        if (len(written) == 0) written = 'none'
        call ctx%write_mess('    IMPR_RESU: wrote ' // path // ' (MED: mesh ' // mesh_name // &
            ', fields ' // written // ')')
    end subroutine print_med_occurrence

    ! The node field of items first..last (one per instant) into the MED file.
    subroutine write_node_steps(out, set, first, last, mesh_name, field_name, st)
        type(med_output_t), intent(inout) :: out
        type(print_set_t), intent(in) :: set
        integer, intent(in) :: first, last
        character(len=*), intent(in) :: mesh_name, field_name
        type(status_t), intent(out) :: st
        type(node_field_t), allocatable :: steps(:)
        integer(i4), allocatable :: numbers(:)
        real(dp), allocatable :: times(:)
        integer :: k
        allocate (steps(last - first + 1), numbers(last - first + 1), times(last - first + 1))
        do k = first, last
            call node_field_of(set%items(k)%f, set%items(k)%name, set%components, &
                steps(k - first + 1))
            numbers(k - first + 1) = -1
            times(k - first + 1) = 0.0_dp
            if (set%items(k)%has_instant) then
                numbers(k - first + 1) = set%items(k)%nume_ordre
                times(k - first + 1) = set%items(k)%inst
            end if
        end do
        call write_med_node_field(out, mesh_name, field_name, steps, numbers, times, &
            set%node_taken, st)
    end subroutine write_node_steps

    ! The element field of items first..last (one per instant) into the MED file.
    subroutine write_cell_steps(out, set, first, last, mesh_name, field_name, st)
        type(med_output_t), intent(inout) :: out
        type(print_set_t), intent(in) :: set
        integer, intent(in) :: first, last
        character(len=*), intent(in) :: mesh_name, field_name
        type(status_t), intent(out) :: st
        type(med_cell_step_t), allocatable :: steps(:)
        integer :: k
        allocate (steps(last - first + 1))
        do k = first, last
            steps(k - first + 1)%f => set%items(k)%f
            if (set%items(k)%has_instant) then
                steps(k - first + 1)%numdt = set%items(k)%nume_ordre
                steps(k - first + 1)%time = set%items(k)%inst
            end if
        end do
        call write_med_cell_field(out, set%mesh, set%model, mesh_name, field_name, steps, &
            field_columns(set%items(first)%f, set%components, set%cell_taken), &
            set%cell_taken, st)
    end subroutine write_cell_steps

    !> The file name of a mesh path without folder and extension (the MED mesh name written
    !> with the results; 'MAIL' when there is none).
    pure function mesh_stem(path) result(stem)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: stem
        integer :: dot
        stem = path(index(path, '/', back=.true.) + 1:)
        dot = index(stem, '.', back=.true.)
        if (dot > 1) stem = stem(1:dot - 1)
        if (len(stem) == 0) stem = 'MAIL'
        if (len(stem) > 64) stem = stem(1:64)
    end function mesh_stem

    ! True when `path` is in `paths`.
    pure logical function any_path(paths, path)
        type(string_t), intent(in) :: paths(:)
        character(len=*), intent(in) :: path
        integer :: k
        any_path = .false.
        do k = 1, size(paths)
            if (paths(k)%s == path) any_path = .true.
        end do
    end function any_path

    ! Records a result file written by this run (ctx%result_files).
    subroutine note_result_file(ctx, path)
        type(run_context_t), intent(inout) :: ctx
        character(len=*), intent(in) :: path
        type(string_t), allocatable :: bigger(:)
        integer :: n
        if (.not. allocated(ctx%result_files)) allocate (ctx%result_files(0))
        if (any_path(ctx%result_files, path)) return
        n = size(ctx%result_files)
        allocate (bigger(n + 1))
        bigger(1:n) = ctx%result_files
        bigger(n + 1)%s = path
        call move_alloc(bigger, ctx%result_files)
    end subroutine note_result_file

    !> The mesh in the plain arrays of result_data (RESULT_CELL_* codes, CSR connectivity).
    !>  st : STATUS_INTERNAL when a cell type has no RESULT_CELL_* code
    subroutine result_mesh_arrays(mesh, cell_types, cell_ptr, cell_nodes, st)
        type(mesh_t), intent(in) :: mesh
        integer, allocatable, intent(out) :: cell_types(:), cell_ptr(:), cell_nodes(:)
        type(status_t), intent(out) :: st
        integer(i4) :: c
        allocate (cell_types(mesh%n_cells))
        do c = 1, mesh%n_cells
            cell_types(c) = cell_type_from_name(CELL_TYPE_NAMES(mesh%cell_type(c)))
            if (cell_types(c) == 0) then
                call set_error(st, STATUS_INTERNAL, 'cell type ' // &
                    trim(CELL_TYPE_NAMES(mesh%cell_type(c))) // ' has no result-file code')
                return
            end if
        end do
        cell_ptr = int(mesh%cell_ptr(1:mesh%n_cells + 1))
        cell_nodes = int(mesh%cell_nodes(1:mesh%cell_ptr(mesh%n_cells + 1) - 1))
    end subroutine result_mesh_arrays

end module impr_resu_command
