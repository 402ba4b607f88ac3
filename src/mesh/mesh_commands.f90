!> Command handler of the mesh layer: LIRE_MAILLAGE (doc/deck-language.md).
module mesh_commands
    use kinds, only: i4
    use status, only: status_t, STATUS_IO_ERROR, STATUS_NOT_IMPLEMENTED
    use strings, only: string_t, to_text
    use deck_concept, only: concept_t
    use deck_command, only: command_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_summary
    use mesh_reader, only: read_mesh
    use mesh_concept, only: mesh_concept_t
    use mesh_command_support, only: relocate_error
    implicit none
    private

    !> Extensions an unbound unit 20 is looked for with, beside the deck, for FORMAT='MED':
    !> .med (Salome's and most tools' name) and .mmed (Code_Aster's test suite's name).
    character(len=*), parameter :: MED_EXTENSIONS(2) = ['.med ', '.mmed']

    public :: run_lire_maillage

contains

    !> LIRE_MAILLAGE(FORMAT='MED'|'ASTER'|'GMSH'|'IDEAS', UNITE=20, NOM_MED): reads the mesh
    !> file (FORMAT='GIBI', in Code_Aster's catalog, is refused at FORMAT), the
    !> parallel and bookkeeping keywords (PARTITIONNEUR, INFO_MED, VERI_MAIL) having no effect;
    !> bound to UNITE (ctx%unit_path; MED is the default FORMAT, as in Code_Aster) and writes
    !> its summary (nodes, cells per type, groups with sizes, bounding box) to the .mess.
    !> An unbound unit 20 is the deck's stem beside the deck: .mail (ASTER), .msh (GMSH), and
    !> for MED <stem>.med or <stem>.mmed, whichever exists (both existing is an error: which
    !> one is meant must be said with --unit 20=PATH).
    !>  result : out, a mesh_concept_t
    !>  st     : out, an unbound unit or a missing file at UNITE (naming the path and the
    !>           --unit option); errors in a text mesh file keep their mesh-file location
    !>           (file:line); errors in a MED file at UNITE, naming the file, and at NOM_MED
    !>           when the mesh name is at fault (several meshes and none named, or no mesh of
    !>           that name: the message lists the file's meshes)
    subroutine run_lire_maillage(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(mesh_concept_t), allocatable :: mc
        character(len=:), allocatable :: format, path, mesh_name
        character(len=100), allocatable :: lines(:)
        type(string_t), allocatable :: notes(:)
        integer(i4) :: unit, k
        logical :: exists
        call cmd%get_text('FORMAT', format, st)
        if (st%failed()) return
        if (format /= 'MED' .and. format /= 'ASTER' .and. format /= 'GMSH' .and. &
            format /= 'IDEAS') then
            call cmd%error_at('FORMAT', 'parasol does not read the ' // format // &
                ' format (it reads MED, ASTER, GMSH and IDEAS meshes: convert the mesh to one ' // &
                'of them)', st, code=STATUS_NOT_IMPLEMENTED)
            return
        end if
        call cmd%get_int('UNITE', unit, st)
        if (st%failed()) return
        mesh_name = ''
        if (format == 'MED' .and. cmd%has('NOM_MED')) then
            call cmd%get_text('NOM_MED', mesh_name, st)
            if (st%failed()) return
        end if
        call mesh_file_path(ctx, cmd, unit, format, path, st)
        if (st%failed()) return
        inquire (file=path, exist=exists)
        if (.not. exists) then
            call cmd%error_at('UNITE', 'mesh file ' // path // ' (unit ' // to_text(unit) // &
                ') does not exist (bind the unit to the mesh with --unit ' // to_text(unit) &
                // '=PATH)', st, code=STATUS_IO_ERROR)
            return
        end if
        allocate (mc)
        if (format == 'MED') then
            call read_mesh(path, mc%mesh, st, format, mesh_name=mesh_name, notes=notes)
            if (st%failed()) then
                call locate_med_error(cmd, st)
                return
            end if
        else
            call read_mesh(path, mc%mesh, st, format)
            if (st%failed()) return
        end if
        lines = mesh_summary(mc%mesh)
        do k = 1, size(lines)
            call ctx%write_mess('    ' // trim(lines(k)))
        end do
        if (allocated(notes)) then
            do k = 1, size(notes)
                call ctx%write_mess('    ' // notes(k)%s)
            end do
        end if
        call move_alloc(mc, result)
    end subroutine run_lire_maillage

    ! The file of the mesh: the bound unit's path, or the default beside the deck.
    subroutine mesh_file_path(ctx, cmd, unit, format, path, st)
        type(run_context_t), intent(in) :: ctx
        type(command_t), intent(in) :: cmd
        integer(i4), intent(in) :: unit
        character(len=*), intent(in) :: format
        character(len=:), allocatable, intent(out) :: path
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: candidate, found
        integer :: k
        logical :: exists
        call ctx%unit_path(unit, format, path, st)
        if (st%failed()) then
            call relocate_error(cmd, 'UNITE', st)
            return
        end if
        if (format /= 'MED' .or. any(ctx%unit_numbers == unit)) return
        ! Unbound unit 20, MED: <stem>.med or <stem>.mmed beside the deck.
        found = ''
        do k = 1, size(MED_EXTENSIONS)
            candidate = ctx%deck_dir // ctx%deck_stem // trim(MED_EXTENSIONS(k))
            inquire (file=candidate, exist=exists)
            if (.not. exists) cycle
            if (len(found) > 0) then
                call cmd%error_at('UNITE', 'both ' // found // ' and ' // candidate // &
                    ' exist beside the deck: say which mesh unit ' // to_text(unit) // &
                    ' is with --unit ' // to_text(unit) // '=PATH', st, code=STATUS_IO_ERROR)
                return
            end if
            found = candidate
        end do
        if (len(found) > 0) then
            path = found
        else
            call cmd%error_at('UNITE', 'mesh file ' // ctx%deck_dir // ctx%deck_stem // &
                '.med (or .mmed) for unit ' // to_text(unit) // ' does not exist (bind the ' &
                // 'unit to the mesh with --unit ' // to_text(unit) // '=PATH)', st, &
                code=STATUS_IO_ERROR)
        end if
    end subroutine mesh_file_path

    ! A MED reader error at the keyword it concerns: NOM_MED when the mesh name is at fault
    ! (at the command when NOM_MED is not written), UNITE otherwise.
    subroutine locate_med_error(cmd, st)
        type(command_t), intent(in) :: cmd
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: key, message
        integer :: code
        key = 'UNITE'
        if (allocated(st%keyword)) then
            if (st%keyword == 'NOM_MED') key = 'NOM_MED'
        end if
        message = st%message
        code = st%code
        call cmd%error_at(key, message, st, code=code)
    end subroutine locate_med_error

end module mesh_commands
