!> IMPR_RESU: prints the fields of results (evol_elas, evol_noli) (listings.md, "IMPR_RESU").
!>  FORMAT='RESULTAT' (default): tables in the `.resu`, one per field and stored instant
!>                    (result_table), restricted to GROUP_NO nodes and NOM_CMP components;
!>  FORMAT='VTK'      : per RESU occurrence `<stem>_<RESULT>.pvd` and one
!>                    `<stem>_<RESULT>_NNNN.vtu` per instant in the output folder;
!>  FORMAT='GMSH'     : per RESU occurrence `<stem>_<RESULT>.msh` in the output folder;
!>  FORMAT='MED'      : the mesh and the fields (result_med, laid out as Code_Aster writes
!>                    them) in the file bound to UNITE (default 80, as Code_Aster) with
!>                    `--unit 80=PATH`, every RESU occurrence in that one file; unbound, one
!>                    `<stem>_<RESULT>.rmed` per occurrence in the output folder. Without
!>                    NOM_CHAM every stored field (DEPL, FORC_NODA, REAC_NODA) is written. A
!>                    file written earlier in the run is added to (Code_Aster adds to the
!>                    file of a unit), not replaced; the mesh goes in once.
!> For VTK and GMSH, a UNITE given in the deck and bound with `--unit N=PATH` replaces the
!> default name: PATH itself for GMSH; for VTK the .pvd is PATH (`.pvd` added when PATH lacks
!> it) and the .vtu files are named after it. Files are named in the .mess.
!>
!> Node fields are built from the equation vectors of the result and its DOF numbering: a
!> node carries a component when it has an equation for it (node_fields_from_result). A
!> non-finite value is never written: the command stops with an error naming node and
!> component instead. The element fields of the DIS_CHOC springs (SIEF_ELGA, VARI_ELGA) are
!> tables per cell and point in the .resu, and cell data for viewers (result_cell_arrays:
!> one array per component, SPRING_STATUS); VTK and Gmsh files also carry GROUP_<name> for
!> every cell group. Without NOM_CHAM, viewers get DEPL and, when the result has DIS_CHOC
!> springs, SIEF_ELGA and VARI_ELGA; the .resu gets DEPL.
module impr_resu_command
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_INTERNAL
    use strings, only: string_t, to_text, to_upper, ends_with
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, find_node_group, nodes_of_group, node_name, CELL_TYPE_NAMES
    use model_dof_numbering, only: component_index, COMPONENT_NAMES, N_COMPONENTS
    use analysis_result, only: result_concept_t, result_find, is_cell_field
    use element_spring_fields, only: SPRING_POINTS
    use result_data, only: node_field_t, cell_type_from_name
    use result_table, only: resultat_table_lines, cell_table_lines
    use result_cell_arrays, only: spring_cell_arrays, group_cell_arrays, split_components, &
        field_components
    use result_data, only: cell_array_t
    use mesh_types, only: cell_name
    use result_vtk, only: write_vtk_series
    use result_gmsh, only: write_gmsh_file
    use result_med, only: med_output_t, med_output_open, med_output_commit, &
        med_output_discard, med_output_mesh, write_med_mesh, write_med_node_field, &
        med_field_name
    use test_resu_command, only: result_of_keyword, relocate
    implicit none
    private

    !> NOM_CHAM printed when the occurrence gives none (Code_Aster prints every field; DEPL
    !> is the one every analysis stores and the one viewers deform the mesh with).
    character(len=*), parameter :: DEFAULT_FIELD = 'DEPL'
    !> FORMAT='MED' without NOM_CHAM: every field a result stores (Code_Aster writes every
    !> field of the result).
    character(len=9), parameter :: MED_DEFAULT_FIELDS(3) = ['DEPL     ', 'FORC_NODA', &
                                                            'REAC_NODA']
    !> Code_Aster's default UNITE of IMPR_RESU for FORMAT='MED' (U4.91.01).
    integer(i4), parameter :: MED_DEFAULT_UNIT = 80

    public :: run_impr_resu, node_fields_from_result, result_mesh_arrays, &
        impr_resu_instants, impr_resu_group_nodes, impr_resu_components

contains

    !> The result of RESULTAT as an analysis result (the writers read its state and mesh).
    !>  st : located at RESULTAT for any other concept
    subroutine analysis_result_of(occ, res, st)
        use result_fields, only: result_fields_t
        type(keyword_set_t), intent(in) :: occ
        type(result_concept_t), pointer, intent(out) :: res
        type(status_t), intent(out) :: st
        class(result_fields_t), pointer :: any
        res => null()
        call result_of_keyword(occ, 'RESULTAT', any, st)
        if (st%failed()) return
        select type (any)
        type is (result_concept_t)
            res => any
        class default
            call occ%error_at('RESULTAT', 'IMPR_RESU prints the results of MECA_STATIQUE ' // &
                'and STAT_NON_LINE, not a ' // any%type_name(), st)
        end select
    end subroutine analysis_result_of

    !> Handler of IMPR_RESU (doc/architecture.md "Writing a command handler").
    !>  st : located errors (RESULTAT of another type, INST/NUME_ORDRE not stored, unknown
    !>       GROUP_NO, a component no node carries, a bound UNITE with several RESU, a
    !>       non-finite value), STATUS_IO_ERROR when a file cannot be written
    subroutine run_impr_resu(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: format, bound_path
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
            call print_occurrence(ctx, format, bound_path, cmd%occurrence('RESU', k), st)
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

    !> One RESU occurrence in the given format.
    subroutine print_occurrence(ctx, format, bound_path, occ, st)
        type(run_context_t), intent(inout) :: ctx
        character(len=*), intent(in) :: format, bound_path
        type(keyword_set_t), intent(in) :: occ
        type(status_t), intent(out) :: st
        type(result_concept_t), pointer :: res
        type(string_t), allocatable :: fields(:), given(:), components(:), sief_cmps(:), &
            vari_cmps(:)
        integer(i4), allocatable :: indices(:)
        call analysis_result_of(occ, res, st)
        if (st%failed()) return
        if (occ%has('NOM_CHAM')) then
            call occ%get_texts('NOM_CHAM', fields, st)
            if (st%failed()) return
        else
            allocate (fields(1))
            fields(1)%s = DEFAULT_FIELD
            ! viewers also get the springs' fields: colour by SPRING_STATUS in one click
            if (format /= 'RESULTAT' .and. size(res%spring_cell) > 0) &
                fields = [fields, string_t('SIEF_ELGA'), string_t('VARI_ELGA')]
        end if
        call occurrence_instants(occ, res, indices, st)
        if (st%failed()) return
        allocate (given(0))
        if (occ%has('NOM_CMP')) call occ%get_texts('NOM_CMP', given, st)
        if (st%failed()) return
        call split_components(res, fields, given, components, sief_cmps, vari_cmps, st)
        if (st%ok()) call impr_resu_components(res, components, st)
        if (st%failed()) then
            call relocate(occ, trim(merge('NOM_CMP ', 'NOM_CHAM', occ%has('NOM_CMP'))), st)
            return
        end if
        select case (format)
        case ('VTK', 'GMSH')
            call write_viewer_file(ctx, format, bound_path, res, fields, components, indices, &
                st, sief_cmps, vari_cmps)
        case default
            call write_tables(ctx, occ, res, fields, components, indices, st, sief_cmps, &
                vari_cmps)
        end select
    end subroutine print_occurrence

    !> The stored instants asked for by INST or NUME_ORDRE (all when neither is given).
    subroutine occurrence_instants(occ, res, indices, st)
        type(keyword_set_t), intent(in) :: occ
        type(result_concept_t), intent(in) :: res
        integer(i4), allocatable, intent(out) :: indices(:)
        type(status_t), intent(out) :: st
        real(dp), allocatable :: insts(:)
        integer(i4), allocatable :: nume_ordres(:)
        if (occ%has('INST')) then
            call occ%get_reals('INST', insts, st)
            if (st%ok()) call impr_resu_instants(res, indices, st, insts=insts)
            if (st%failed()) call relocate(occ, 'INST', st)
        else if (occ%has('NUME_ORDRE')) then
            call occ%get_ints('NUME_ORDRE', nume_ordres, st)
            if (st%failed()) return
            call impr_resu_instants(res, indices, st, nume_ordres=nume_ordres)
            if (st%failed()) call relocate(occ, 'NUME_ORDRE', st)
        else
            call impr_resu_instants(res, indices, st)
        end if
    end subroutine occurrence_instants

    !> FORMAT='RESULTAT': one table per field and instant in the .resu.
    !>  sief_cmps, vari_cmps : in, the components of the element fields (empty: all)
    subroutine write_tables(ctx, occ, res, fields, components, indices, st, sief_cmps, &
                            vari_cmps)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(result_concept_t), intent(in) :: res
        type(string_t), intent(in) :: fields(:), components(:)
        integer(i4), intent(in) :: indices(:)
        type(status_t), intent(out) :: st
        type(string_t), intent(in) :: sief_cmps(:), vari_cmps(:)
        type(string_t), allocatable :: groups(:), names(:), lines(:)
        integer(i4), allocatable :: nodes(:)
        type(node_field_t) :: field
        integer :: f, k, i
        allocate (names(res%mesh%n_nodes))
        do i = 1, res%mesh%n_nodes
            names(i)%s = node_name(res%mesh, int(i, i4))
        end do
        nodes = [(int(i, i4), i = 1, res%mesh%n_nodes)]
        if (occ%has('GROUP_NO')) then
            call occ%get_texts('GROUP_NO', groups, st)
            if (st%ok()) call impr_resu_group_nodes(res%mesh, groups, nodes, st)
            if (st%failed()) then
                call relocate(occ, 'GROUP_NO', st)
                return
            end if
        end if
        do f = 1, size(fields)
            do k = 1, size(indices)
                if (is_cell_field(fields(f)%s)) then
                    if (fields(f)%s == 'SIEF_ELGA') then
                        call spring_table(res, fields(f)%s, sief_cmps, indices(k), lines)
                    else
                        call spring_table(res, fields(f)%s, vari_cmps, indices(k), lines)
                    end if
                    do i = 1, size(lines)
                        call ctx%write_resu(lines(i)%s)
                    end do
                    cycle
                end if
                call node_fields_from_result(res, fields(f)%s, components, indices(k), field, st)
                if (st%failed()) return
                call resultat_table_lines(res%name, int(res%nume_ordre(indices(k))), &
                    res%inst(indices(k)), field, names, lines, node_list=int(nodes))
                do i = 1, size(lines)
                    call ctx%write_resu(lines(i)%s)
                end do
            end do
        end do
        call ctx%write_mess('    IMPR_RESU: ' // to_text(size(fields, kind=i4) * &
            size(indices, kind=i4)) // ' table(s) of ' // res%name // ' written to the .resu')
    end subroutine write_tables

    !> A RESULTAT table of an element field at stored instant `stored`: a row per spring
    !> and point (result_table cell_table_lines).
    subroutine spring_table(res, field, components, stored, lines)
        type(result_concept_t), intent(in) :: res
        character(len=*), intent(in) :: field
        type(string_t), intent(in) :: components(:)
        integer(i4), intent(in) :: stored
        type(string_t), allocatable, intent(out) :: lines(:)
        type(cell_array_t), allocatable :: arrays(:)
        type(string_t), allocatable :: names(:), cells(:)
        real(dp), allocatable :: values(:, :)
        integer(i4) :: a, k
        call spring_cell_arrays(res, stored, field, components, arrays)
        names = components
        if (size(names) == 0) names = field_components(res, field)
        allocate (cells(size(res%spring_cell)), values(size(names), size(res%spring_cell)))
        do k = 1, size(res%spring_cell)
            cells(k)%s = cell_name(res%mesh, res%spring_cell(k))
            do a = 1, size(names)
                values(a, k) = arrays(a)%values(res%spring_cell(k))
            end do
        end do
        call cell_table_lines(res%name, int(res%nume_ordre(stored)), res%inst(stored), field, &
            names, cells, SPRING_POINTS, values, lines)
    end subroutine spring_table

    !> FORMAT='VTK' or 'GMSH': the mesh of the result with every field of every instant:
    !> node fields as point data, element fields and the cell groups as cell data.
    !>  sief_cmps, vari_cmps : in, the components of the element fields (empty: all)
    subroutine write_viewer_file(ctx, format, bound_path, res, fields, components, indices, &
                                 st, sief_cmps, vari_cmps)
        type(run_context_t), intent(inout) :: ctx
        character(len=*), intent(in) :: format, bound_path
        type(result_concept_t), intent(in) :: res
        type(string_t), intent(in) :: fields(:), components(:)
        integer(i4), intent(in) :: indices(:)
        type(status_t), intent(out) :: st
        type(string_t), intent(in) :: sief_cmps(:), vari_cmps(:)
        type(node_field_t), allocatable :: node_fields(:, :)
        type(cell_array_t), allocatable :: cells(:, :)
        type(string_t), allocatable :: node_names(:)
        integer, allocatable :: cell_types(:), cell_ptr(:), cell_nodes(:)
        character(len=:), allocatable :: path
        integer :: f, k
        call result_mesh_arrays(res%mesh, cell_types, cell_ptr, cell_nodes, st)
        if (st%failed()) return
        allocate (node_names(0))
        do f = 1, size(fields)
            if (.not. is_cell_field(fields(f)%s)) node_names = [node_names, fields(f)]
        end do
        allocate (node_fields(size(node_names), size(indices)))
        do k = 1, size(indices)
            do f = 1, size(node_names)
                call node_fields_from_result(res, node_names(f)%s, components, indices(k), &
                                             node_fields(f, k), st)
                if (st%failed()) return
            end do
        end do
        call viewer_cell_arrays(res, fields, indices, sief_cmps, vari_cmps, cells)
        if (format == 'VTK') then
            path = bound_path
            if (len(path) == 0) path = ctx%output_path('_' // res%name // '.pvd')
            if (.not. ends_with(path, '.pvd')) path = path // '.pvd'
            call write_vtk_series(path(1:len(path) - 4), res%mesh%coords, cell_types, &
                cell_ptr, cell_nodes, res%inst(indices), node_fields, st, cells)
            if (st%ok()) call ctx%write_mess('    IMPR_RESU: wrote ' // path // ' and ' // &
                to_text(size(indices, kind=i4)) // ' .vtu file(s) next to it')
        else
            path = bound_path
            if (len(path) == 0) path = ctx%output_path('_' // res%name // '.msh')
            call write_gmsh_file(path, res%mesh%coords, cell_types, cell_ptr, cell_nodes, &
                res%inst(indices), int(res%nume_ordre(indices)), node_fields, st, cells)
            if (st%ok()) call ctx%write_mess('    IMPR_RESU: wrote ' // path)
        end if
    end subroutine write_viewer_file

    !> The cell data of each instant: the cell groups, then the element fields asked for
    !> (SPRING_STATUS once, after them).
    !>  cells : out, (n_arrays, size(indices))
    subroutine viewer_cell_arrays(res, fields, indices, sief_cmps, vari_cmps, cells)
        type(result_concept_t), intent(in) :: res
        type(string_t), intent(in) :: fields(:), sief_cmps(:), vari_cmps(:)
        integer(i4), intent(in) :: indices(:)
        type(cell_array_t), allocatable, intent(out) :: cells(:, :)
        type(cell_array_t), allocatable :: groups(:), one(:), all(:)
        integer :: f, k
        logical :: status_written
        call group_cell_arrays(res%mesh, groups)
        do k = 1, size(indices)
            all = groups
            status_written = .false.
            do f = 1, size(fields)
                if (.not. is_cell_field(fields(f)%s)) cycle
                if (fields(f)%s == 'SIEF_ELGA') then
                    call spring_cell_arrays(res, indices(k), fields(f)%s, sief_cmps, one)
                else
                    call spring_cell_arrays(res, indices(k), fields(f)%s, vari_cmps, one)
                end if
                ! the last array is SPRING_STATUS: keep it once
                if (status_written) then
                    all = [all, one(1:size(one) - 1)]
                else
                    all = [all, one]
                end if
                status_written = .true.
            end do
            if (k == 1) allocate (cells(size(all), size(indices)))
            cells(:, k) = all
        end do
    end subroutine viewer_cell_arrays

    !> FORMAT='MED': every RESU occurrence into the file of UNITE (default 80) when it is
    !> bound, else into one <stem>_<RESULT>.rmed per occurrence.
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

    !> One RESU occurrence into a MED file: the mesh (once per file) and each field.
    subroutine print_med_occurrence(ctx, bound_path, occ, st)
        type(run_context_t), intent(inout) :: ctx
        character(len=*), intent(in) :: bound_path
        type(keyword_set_t), intent(in) :: occ
        type(status_t), intent(out) :: st
        type(result_concept_t), pointer :: res
        type(string_t), allocatable :: fields(:), components(:), groups(:)
        integer(i4), allocatable :: indices(:), nodes(:)
        logical, allocatable :: selected(:)
        type(node_field_t), allocatable :: steps(:)
        type(med_output_t) :: out
        character(len=:), allocatable :: path, mesh_name, written
        logical :: append, exists
        integer :: f, k
        call analysis_result_of(occ, res, st)
        if (st%failed()) return
        if (occ%has('NOM_CHAM')) then
            call occ%get_texts('NOM_CHAM', fields, st)
            if (st%failed()) return
        else
            allocate (fields(size(MED_DEFAULT_FIELDS)))
            do f = 1, size(fields)
                fields(f)%s = trim(MED_DEFAULT_FIELDS(f))
            end do
        end if
        do f = 1, size(fields)
            if (.not. is_cell_field(fields(f)%s)) cycle
            ! an ELGA field in MED needs a Gauss-point localisation the MED plug-in does not
            ! write yet
            call occ%error_at('NOM_CHAM', fields(f)%s // ' is not written to MED yet (the ' // &
                'springs'' element fields go to FORMAT=''VTK'', ''GMSH'' and ''RESULTAT'')', st)
            return
        end do
        call occurrence_instants(occ, res, indices, st)
        if (st%failed()) return
        allocate (components(0))
        if (occ%has('NOM_CMP')) call occ%get_texts('NOM_CMP', components, st)
        if (st%failed()) return
        call impr_resu_components(res, components, st)
        if (st%failed()) then
            call relocate(occ, 'NOM_CMP', st)
            return
        end if
        allocate (selected(res%mesh%n_nodes), source=.true.)
        if (occ%has('GROUP_NO')) then
            call occ%get_texts('GROUP_NO', groups, st)
            if (st%ok()) call impr_resu_group_nodes(res%mesh, groups, nodes, st)
            if (st%failed()) then
                call relocate(occ, 'GROUP_NO', st)
                return
            end if
            selected = .false.
            selected(nodes) = .true.
        end if
        path = bound_path
        if (len(path) == 0) path = ctx%output_path('_' // res%name // '.rmed')
        append = .false.
        if (allocated(ctx%result_files)) append = any_path(ctx%result_files, path)
        call med_output_open(out, path, append, st)
        if (st%failed()) return
        call med_output_mesh(out, res%mesh, mesh_stem(res%mesh%file), mesh_name, exists, st)
        if (st%ok() .and. .not. exists) call write_med_mesh(out, res%mesh, mesh_name, st)
        written = ''
        do f = 1, size(fields)
            if (st%failed()) exit
            if (allocated(steps)) deallocate (steps)
            allocate (steps(size(indices)))
            do k = 1, size(indices)
                call node_fields_from_result(res, fields(f)%s, components, indices(k), &
                                             steps(k), st)
                if (st%failed()) exit
            end do
            if (st%failed()) exit
            call write_med_node_field(out, mesh_name, med_field_name(res%name, fields(f)%s), &
                steps, res%nume_ordre(indices), res%inst(indices), selected, st)
            if (f > 1) written = written // ', '
            written = written // med_field_name(res%name, fields(f)%s)
        end do
        if (st%failed()) then
            call med_output_discard(out)
            return
        end if
        call med_output_commit(out, st)
        if (st%failed()) return
        call note_result_file(ctx, path)
        call ctx%write_mess('    IMPR_RESU: wrote ' // path // ' (MED: mesh ' // mesh_name // &
            ', fields ' // written // ', ' // to_text(size(indices, kind=i4)) // ' instant(s))')
    end subroutine print_med_occurrence

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

    !> A node field of a result at one stored instant.
    !>  res        : in, the result
    !>  field      : in, DEPL, FORC_NODA or REAC_NODA
    !>  components : in, the component names in output order; empty = every component some
    !>               node of the numbering carries, in the order DX DY DZ DRX DRY DRZ
    !>  index      : in, stored instant, 1..res%n_stored
    !>  node_field : out, values(n_components, n_nodes) and mask (node has an equation for it)
    !>  st         : STATUS_MODEL_ERROR for an unknown field or component, an index out of
    !>               range, or a non-finite value (naming node and component)
    subroutine node_fields_from_result(res, field, components, index, node_field, st)
        type(result_concept_t), intent(in) :: res
        character(len=*), intent(in) :: field
        type(string_t), intent(in) :: components(:)
        integer(i4), intent(in) :: index
        type(node_field_t), intent(out) :: node_field
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        integer(i4), allocatable :: comps(:)
        integer(i4) :: n, c, eq
        if (index < 1 .or. index > res%n_stored) then
            call set_error(st, STATUS_MODEL_ERROR, 'instant ' // to_text(index) // &
                           ' is not stored (the result holds ' // to_text(res%n_stored) // ')')
            return
        end if
        names = components
        call impr_resu_components(res, names, st)
        if (st%failed()) return
        allocate (comps(size(names)))
        do c = 1, size(names)
            comps(c) = component_index(to_upper(names(c)%s))
        end do
        node_field%name = to_upper(field)
        node_field%components = names
        allocate (node_field%values(size(names), res%mesh%n_nodes), source=0.0_dp)
        allocate (node_field%mask(size(names), res%mesh%n_nodes), source=.false.)
        do n = 1, min(res%mesh%n_nodes, res%dofs%n_nodes)
            do c = 1, size(names)
                eq = res%dofs%equation(comps(c), n)
                if (eq == 0) cycle
                node_field%mask(c, n) = .true.
                call field_value(res, node_field%name, eq, index, node_field%values(c, n), st)
                if (st%failed()) return
                if (.not. ieee_is_finite(node_field%values(c, n))) then
                    call set_error(st, STATUS_MODEL_ERROR, field // ' at node ' // &
                        node_name(res%mesh, n) // ', component ' // names(c)%s // &
                        ' is not a finite number; not written')
                    return
                end if
            end do
        end do
    end subroutine node_fields_from_result

    !> Value of equation `eq` of a field at stored instant `index`.
    subroutine field_value(res, field, eq, index, value, st)
        type(result_concept_t), intent(in) :: res
        character(len=*), intent(in) :: field
        integer(i4), intent(in) :: eq, index
        real(dp), intent(out) :: value
        type(status_t), intent(out) :: st
        value = 0.0_dp
        select case (field)
        case ('DEPL')
            value = res%depl(eq, index)
        case ('FORC_NODA')
            value = res%forc_noda(eq, index)
        case ('REAC_NODA')
            value = res%reac_noda(eq, index)
        case default
            call set_error(st, STATUS_MODEL_ERROR, 'field ' // field // &
                           ' is not stored (DEPL, FORC_NODA, REAC_NODA)')
        end select
    end subroutine field_value

    !> Checks NOM_CMP against the result, or fills it in when empty.
    !>  components : inout, component names; empty on entry = every component some node
    !>               carries (order DX DY DZ DRX DRY DRZ)
    !>  st         : STATUS_MODEL_ERROR when a name is not a component or no node carries it
    subroutine impr_resu_components(res, components, st)
        type(result_concept_t), intent(in) :: res
        type(string_t), allocatable, intent(inout) :: components(:)
        type(status_t), intent(out) :: st
        logical :: carried(N_COMPONENTS)
        integer(i4) :: c, k, n
        carried = .false.
        if (allocated(res%dofs%equation)) carried = any(res%dofs%equation /= 0, dim=2)
        if (size(components) == 0) then
            deallocate (components)
            allocate (components(count(carried)))
            n = 0
            do c = 1, N_COMPONENTS
                if (.not. carried(c)) cycle
                n = n + 1
                components(n)%s = trim(COMPONENT_NAMES(c))
            end do
            return
        end if
        do k = 1, size(components)
            c = component_index(to_upper(components(k)%s))
            if (c == 0) then
                call set_error(st, STATUS_MODEL_ERROR, components(k)%s // &
                               ' is not a component (DX DY DZ DRX DRY DRZ)')
                return
            else if (.not. carried(c)) then
                call set_error(st, STATUS_MODEL_ERROR, 'no node of the result carries ' // &
                               'component ' // components(k)%s // ' (its elements do not use it)')
                return
            end if
        end do
    end subroutine impr_resu_components

    !> Stored instants (indices 1..n_stored) asked for by INST or NUME_ORDRE, in the order
    !> given; every stored instant when neither is present.
    !>  st : STATUS_MODEL_ERROR from result_find (the instant and what is stored)
    subroutine impr_resu_instants(res, indices, st, insts, nume_ordres)
        type(result_concept_t), intent(in) :: res
        integer(i4), allocatable, intent(out) :: indices(:)
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: insts(:)
        integer(i4), intent(in), optional :: nume_ordres(:)
        integer(i4) :: k
        if (present(insts)) then
            allocate (indices(size(insts)))
            do k = 1, size(insts)
                call result_find(res, indices(k), st, inst=insts(k))
                if (st%failed()) return
            end do
        else if (present(nume_ordres)) then
            allocate (indices(size(nume_ordres)))
            do k = 1, size(nume_ordres)
                call result_find(res, indices(k), st, nume_ordre=nume_ordres(k))
                if (st%failed()) return
            end do
        else
            indices = [(k, k = 1, res%n_stored)]
        end if
    end subroutine impr_resu_instants

    !> The nodes of the groups, in group order, each node once.
    !>  st : STATUS_MESH_ERROR naming an unknown group (with a did-you-mean)
    subroutine impr_resu_group_nodes(mesh, groups, nodes, st)
        type(mesh_t), intent(in) :: mesh
        type(string_t), intent(in) :: groups(:)
        integer(i4), allocatable, intent(out) :: nodes(:)
        type(status_t), intent(out) :: st
        logical, allocatable :: taken(:)
        integer(i4), allocatable :: members(:), found(:)
        integer(i4) :: g, k, n, m
        allocate (taken(mesh%n_nodes), source=.false.)
        allocate (found(mesh%n_nodes))
        n = 0
        do k = 1, size(groups)
            g = find_node_group(mesh, groups(k)%s, st)
            if (st%failed()) return
            members = nodes_of_group(mesh, g)
            do m = 1, size(members)
                if (taken(members(m))) cycle
                taken(members(m)) = .true.
                n = n + 1
                found(n) = members(m)
            end do
        end do
        nodes = found(1:n)
    end subroutine impr_resu_group_nodes

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
