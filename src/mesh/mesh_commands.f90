!> Command handlers of the mesh layer: LIRE_MAILLAGE, PRE_GIBI (doc/deck-language.md,
!> doc/mesh-commands.md).
module mesh_commands
    use kinds, only: i4
    use status, only: status_t, STATUS_IO_ERROR, STATUS_NOT_IMPLEMENTED
    use strings, only: string_t, to_text
    use deck_concept, only: concept_t
    use deck_command, only: command_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, mesh_summary, first_rank_name_conflict
    use mesh_reader, only: read_mesh
    use mesh_concept, only: mesh_concept_t
    use mesh_command_support, only: relocate_error, warn_at
    use mesh_gibi_reader, only: gibi_to_aster
    use atomic_file, only: atomic_file_t, open_atomic
    implicit none
    private

    !> Extensions an unbound unit 20 is looked for with, beside the deck, for FORMAT='MED':
    !> .med (Salome's and most tools' name) and .mmed (Code_Aster's test suite's name).
    character(len=*), parameter :: MED_EXTENSIONS(2) = ['.med ', '.mmed']

    public :: run_lire_maillage, run_pre_gibi

contains

    !> LIRE_MAILLAGE(FORMAT='MED'|'ASTER'|'GMSH'|'GIBI'|'IDEAS', UNITE=20, NOM_MED,
    !> CREA_GROUP_COUL): reads the mesh file (GIBI as PRE_GIBI converts it, IDEAS as
    !> PRE_IDEAS does: mesh_ideas_reader), the
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
        character(len=:), allocatable :: format, path, mesh_name, colours
        character(len=100), allocatable :: lines(:)
        type(string_t), allocatable :: notes(:)
        integer(i4) :: unit, k
        logical :: exists
        call cmd%get_text('FORMAT', format, st)
        if (st%failed()) return
        if (format /= 'MED' .and. format /= 'ASTER' .and. format /= 'GMSH' .and. &
            format /= 'GIBI' .and. format /= 'IDEAS') then
            call cmd%error_at('FORMAT', 'parasol does not read the ' // format // &
                ' format (it reads MED, ASTER, GMSH, GIBI and IDEAS meshes: convert the ' // &
                'mesh to one of them)', st, code=STATUS_NOT_IMPLEMENTED)
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
        else if (format == 'IDEAS') then
            call cmd%get_text('CREA_GROUP_COUL', colours, st)
            if (st%failed()) return
            call read_mesh(path, mc%mesh, st, format, notes=notes, &
                           colour_groups=colours == 'OUI')
            if (st%failed()) return
        else
            call read_mesh(path, mc%mesh, st, format, notes=notes)
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
        call warn_rank_names(ctx, cmd, mc%mesh)
        call move_alloc(mc, result)
    end subroutine run_lire_maillage

    !> An alarm when the file gives a node (a cell) a name that reads as another one's
    !> number (the file names node 4 N5): a command's NOEUD='N5' means node 5, as code_aster
    !> 17 reads it (mesh_types entity_by_number), not the node the file calls N5.
    subroutine warn_rank_names(ctx, cmd, mesh)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        type(mesh_t), intent(in) :: mesh
        character(len=:), allocatable :: name, word
        integer(i4) :: rank
        integer :: w
        do w = 1, 2
            if (w == 1) then
                call first_rank_name_conflict(mesh, 'N', rank, name)
                word = 'node'
            else
                call first_rank_name_conflict(mesh, 'M', rank, name)
                word = 'cell'
            end if
            if (rank == 0) cycle
            call warn_at(ctx, cmd, '', 'the file names ' // word // ' ' // to_text(rank) // &
                ' ' // name // ', but a command''s ' // name // ' is ' // word // ' ' // &
                digits_of(name) // ': as code_aster 17, which keeps no ' // word // &
                ' names, parasol reads a name made of a number as that number')
        end do
    end subroutine warn_rank_names

    !> The digits of a name N<k>, M<k> or <k>.
    function digits_of(name) result(digits)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: digits
        digits = name
        if (len(name) > 0) then
            if (name(1:1) == 'N' .or. name(1:1) == 'M') digits = name(2:)
        end if
    end function digits_of

    !> PRE_GIBI(UNITE_GIBI=19, UNITE_MAILLAGE=20): the GIBI file of UNITE_GIBI converted as
    !> Code_Aster converts it (mesh_gibi_reader) and written as a .mail on UNITE_MAILLAGE: the
    !> file bound to that unit (replaced, as Code_Aster replaces it), else <stem>.<unit> in
    !> the output folder, the unit then bound to it so that LIRE_MAILLAGE(FORMAT='ASTER',
    !> UNITE=...) reads it. Cells of every type Cast3M has are written (LIRE_MAILLAGE refuses
    !> those parasol's meshes do not hold).
    !>  st : out, an unbound UNITE_GIBI or a missing file at UNITE_GIBI; errors in the GIBI
    !>       file at its line; a file that cannot be written at UNITE_MAILLAGE
    subroutine run_pre_gibi(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        integer(i4) :: unit_in, unit_out, k
        character(len=:), allocatable :: path, out_path, text
        type(string_t), allocatable :: notes(:)
        type(atomic_file_t) :: file
        logical :: exists, bound
        if (allocated(result)) deallocate (result)
        call cmd%get_int('UNITE_GIBI', unit_in, st)
        if (st%ok()) call cmd%get_int('UNITE_MAILLAGE', unit_out, st)
        if (st%failed()) return
        call ctx%unit_path(unit_in, 'GIBI', path, st)
        if (st%failed()) then
            call relocate_error(cmd, 'UNITE_GIBI', st)
            return
        end if
        inquire (file=path, exist=exists)
        if (.not. exists) then
            call cmd%error_at('UNITE_GIBI', 'GIBI file ' // path // ' (unit ' // &
                to_text(unit_in) // ') does not exist', st, code=STATUS_IO_ERROR)
            return
        end if
        call gibi_to_aster(path, text, notes, st)
        if (st%failed()) return
        bound = .false.
        if (allocated(ctx%unit_numbers)) bound = any(ctx%unit_numbers == unit_out)
        if (bound) then
            call ctx%unit_path(unit_out, 'ASTER', out_path, st)
            if (st%failed()) return
        else
            out_path = ctx%output_path('.' // to_text(unit_out))
        end if
        call open_atomic(file, out_path, st)
        if (st%ok()) then
            call file%write_text(text)
            call file%commit(st)
        end if
        if (st%failed()) then
            call relocate_error(cmd, 'UNITE_MAILLAGE', st)
            return
        end if
        if (.not. bound) call ctx%bind_unit(unit_out, out_path)
        call ctx%write_mess('    PRE_GIBI: ' // path // ' written as a .mail to ' // out_path // &
                            ' (unit ' // to_text(unit_out) // ')')
        do k = 1, size(notes)
            call ctx%write_mess('    ' // notes(k)%s)
        end do
    end subroutine run_pre_gibi

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
