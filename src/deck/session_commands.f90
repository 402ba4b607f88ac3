!> The session commands: DEBUT, POURSUITE and FIN (start, continuation and end of a command
!> file), DEBUG, DEFI_FICHIER (logical units and files) and DETRUIRE (forgetting names).
!> The bookkeeping keywords of DEBUT, POURSUITE, FIN and DEBUG (CODE, ERREUR, MEMOIRE,
!> RESERVE_CPU, ...) are checked by the catalog and have no effect.
!> FIN marks the file finished (a later command is an error); after the last file the run
!> pipeline (cli) writes the verdict and commits .mess and .resu. In a session of several
!> command files (an export file), POURSUITE() makes the names of the earlier files
!> defined again, as Code_Aster's POURSUITE restores the database the previous file saved;
!> DEBUT() in a later file starts a new session instead. Both also run in the check pass
!> (at_check), so that the check pass sees the same names as the run.
module session_commands
    use kinds, only: i4, i8
    use strings, only: string_t, to_text, starts_with
    use system_error, only: make_folder, errno_text
    use status, only: status_t, set_error, STATUS_DECK_ERROR
    use deck_value, only: value_t, int_value, append_string, VK_CONCEPT
    use deck_concept, only: concept_t, concept_display_name
    use deck_command, only: command_t, concept_ref_t, keyword_set_t
    use run_context, only: run_context_t, SCOPE_SESSION
    implicit none
    private
    public :: run_debut, run_poursuite, run_fin, run_debug, run_defi_fichier, run_detruire

    !> The units DEFI_FICHIER hands out when none is given, from the top (Code_Aster's
    !> LogicalUnitFile: 19 to 99, the last first).
    integer, parameter :: FREE_UNIT_MIN = 19, FREE_UNIT_MAX = 99
    !> Longest FICHIER (Code_Aster's LongStr(1, 255)).
    integer, parameter :: MAX_FILE_NAME = 255

contains

    !> DEBUT(): writes the start of the run to the .mess. In a command file after the
    !> first, a new session: the earlier files' names are not carried over.
    subroutine run_debut(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        integer :: restored
        if (allocated(result)) deallocate (result)     ! DEBUT has no result
        if (cmd%n < 0) return
        call ctx%write_mess('    -> start of the deck ' // ctx%deck_name)
        if (ctx%file_index > 1 .and. ctx%stashed) then
            call ctx%continue_session(.true., restored)
            call ctx%write_mess('    -> a new session: the names of the earlier command ' // &
                                'files are not carried over (POURSUITE() would continue it)')
        end if
    end subroutine run_debut

    !> POURSUITE(): continues the session of the previous command file: its names
    !> (concepts, functions, values) are defined again.
    !>  st : out, located at the command: POURSUITE in the first command file (nothing to
    !>       continue), or a second POURSUITE in the same file
    subroutine run_poursuite(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        integer :: restored
        if (allocated(result)) deallocate (result)     ! POURSUITE has no result
        if (cmd%n < 0) return
        if (ctx%file_index <= 1) then
            call set_error(st, STATUS_DECK_ERROR, 'no session to continue: ' // &
                ctx%deck_name // ' is the first command file (start it with DEBUT(); ' // &
                'POURSUITE() opens a following file, e.g. CASE.com1 after CASE.comm in an ' // &
                'export file)')
            return
        end if
        if (ctx%continued .or. .not. ctx%stashed) then
            call set_error(st, STATUS_DECK_ERROR, 'the session is already continued or ' // &
                'restarted in this file (one DEBUT() or POURSUITE() per command file)')
            return
        end if
        call ctx%continue_session(.false., restored)
        call ctx%write_mess('    -> the session continues: ' // to_text(int(restored, i4)) // &
                            ' name(s) of the earlier command files defined again')
    end subroutine run_poursuite

    !> FIN(): the end of the deck; the listings are closed by the pipeline right after.
    subroutine run_fin(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        if (allocated(result)) deallocate (result)     ! FIN has no result
        if (cmd%n < 0) return
        ctx%finished = .true.
        call ctx%write_mess('    -> end of the deck: listings closed')
    end subroutine run_fin

    !> DEBUG(...): developers' checks between two commands in Code_Aster; nothing to do.
    subroutine run_debug(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        if (allocated(result)) deallocate (result)
        if (cmd%n < 0 .or. st%failed()) return
        call ctx%write_mess('    -> no effect in parasol')
    end subroutine run_debug

    !> DEFI_FICHIER (U4.12.03): ASSOCIER or RESERVER binds a logical unit to a file, as the
    !> export file's F lines do (IMPR_RESU, LIRE_TABLE ... with UNITE=U then use it);
    !> without UNITE, the highest free unit of 19..99 is taken and is the command's result
    !> (`U = DEFI_FICHIER(FICHIER='f.med')`). Without FICHIER the file is fort.U. A relative
    !> FICHIER is in the output folder, where parasol writes (ACCES='OLD', a file to read:
    !> beside the deck, else in the output folder; it must exist). LIBERER frees the unit
    !> given by UNITE or FICHIER. TYPE (ASCII, BINARY, LIBRE) is recorded: parasol's
    !> readers and writers know their formats; ACCES='NEW' and 'APPEND' are the writers'
    !> (a file is written whole, IMPR_RESU MED adds to the file of its unit).
    subroutine run_defi_fichier(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: action, name, path, kind, access
        integer :: unit, k
        logical :: found, exists
        if (allocated(result)) deallocate (result)
        call cmd%get_text('ACTION', action, st)
        if (st%failed()) return
        name = ''
        if (cmd%has('FICHIER')) then
            call cmd%get_text('FICHIER', name, st)
            if (st%failed()) return
            if (len_trim(name) == 0 .or. len(name) > MAX_FILE_NAME) then
                call cmd%error_at('FICHIER', 'a file name of 1 to ' // &
                    to_text(int(MAX_FILE_NAME, i4)) // ' characters (Code_Aster''s ' // &
                    'LongStr(1, 255)), got ' // to_text(int(len(name), i4)), st); return
            end if
        end if
        unit = 0
        if (cmd%has('UNITE')) then
            call cmd%get_int('UNITE', unit, st)
            if (st%failed()) return
        end if
        if (action == 'LIBERER') then
            if (unit == 0) unit = ctx%unit_of_path(file_path(name, .false.))
            if (unit == 0) unit = ctx%unit_of_path(file_path(name, .true.))
            if (unit == 0) then
                call ctx%write_mess('    -> ' // name // ' is on no logical unit: nothing ' // &
                                    'to free')
                return
            end if
            call ctx%release_unit(unit, found)
            if (found) then
                call ctx%write_mess('    -> logical unit ' // to_text(int(unit, i4)) // ' freed')
            else
                call ctx%write_mess('    -> logical unit ' // to_text(int(unit, i4)) // &
                                    ' was bound to no file: nothing to free')
            end if
            return
        end if
        call cmd%get_text('TYPE', kind, st)
        if (st%ok()) call cmd%get_text('ACCES', access, st)
        if (st%failed()) return
        if (unit == 0) then
            do k = FREE_UNIT_MAX, FREE_UNIT_MIN, -1
                if (.not. bound(k)) then
                    unit = k; exit
                end if
            end do
            if (unit == 0) then
                call set_error(st, STATUS_DECK_ERROR, 'no free logical unit left in ' // &
                    to_text(int(FREE_UNIT_MIN, i4)) // '..' // to_text(int(FREE_UNIT_MAX, i4)) &
                    // ' (free some with DEFI_FICHIER(ACTION=''LIBERER'', UNITE=...))'); return
            end if
            ctx%plain_result = int_value(int(unit, i8))
            ctx%has_plain_result = .true.
        end if
        if (len(name) == 0) name = 'fort.' // to_text(int(unit, i4))
        path = file_path(name, access == 'OLD')
        if (access == 'OLD') then
            inquire (file=path, exist=exists)
            if (.not. exists) then
                call cmd%error_at('FICHIER', 'file not found: ' // path // ' (ACCES=''OLD'' ' // &
                    'reads an existing file; a relative name is beside the deck or in the ' // &
                    'output folder)', st); return
            end if
        end if
        ! Code_Aster's runner (run_aster) makes REPE_IN and REPE_OUT in the working
        ! directory of every run, so decks write to REPE_OUT/... without making it: the
        ! output folder is parasol's working directory, so REPE_OUT is made there when a
        ! deck names a file in it.
        if (.not. ctx%checking .and. access /= 'OLD' .and. &
            (starts_with(name, 'REPE_OUT/') .or. starts_with(name, './REPE_OUT/'))) then
            k = make_folder(ctx%in_outdir('REPE_OUT'))
            if (k /= 0) then
                call cmd%error_at('FICHIER', 'cannot make the folder ' // &
                    ctx%in_outdir('REPE_OUT') // ' for ' // name // ': ' // errno_text(k), st)
                return
            end if
        end if
        call ctx%release_unit(unit, found)
        call ctx%bind_unit(unit, path)
        call ctx%write_mess('    -> logical unit ' // to_text(int(unit, i4)) // ' bound to ' // &
            path // ' (' // action // ', TYPE=' // kind // ', ACCES=' // access // ')')
    contains
        logical function bound(u)
            integer, intent(in) :: u
            bound = any(ctx%unit_numbers == u)
        end function bound
        !> A relative name: in the output folder; one to read: beside the deck if it is there.
        function file_path(file, reading) result(out)
            character(len=*), intent(in) :: file
            logical, intent(in) :: reading
            character(len=:), allocatable :: out
            logical :: there
            out = file
            if (len(file) == 0) return
            if (file(1:1) == '/') return
            if (reading) then
                inquire (file=ctx%deck_dir // file, exist=there)
                if (there) then
                    out = ctx%deck_dir // file; return
                end if
            end if
            out = ctx%in_outdir(file)
        end function file_path
    end subroutine run_defi_fichier

    !> DETRUIRE(NOM=(A, B)): the names bound to these concepts are forgotten (Python's del,
    !> as Code_Aster deletes them from the command file's namespace); a later use is an
    !> "is not defined" error, a later assignment binds the name anew. The concepts stay
    !> alive for the concepts that refer to them.
    subroutine run_detruire(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(concept_ref_t), allocatable :: refs(:), more(:)
        type(keyword_set_t) :: occ
        type(string_t), allocatable :: gone(:)
        character(len=:), allocatable :: names
        integer :: k, j
        logical :: forgotten
        if (allocated(result)) deallocate (result)
        allocate (refs(0))
        if (cmd%has('NOM')) then
            call cmd%get_concepts('NOM', refs, st)
            if (st%failed()) return
        end if
        do k = 1, cmd%count('CONCEPT')
            occ = cmd%occurrence('CONCEPT', k)
            call occ%get_concepts('NOM', more, st)
            if (st%failed()) return
            refs = [refs, more]
        end do
        allocate (gone(0))
        do k = 1, size(refs)
            j = ctx%nsymbol
            do while (j >= 1)
                if (ctx%symbols(j)%scope == SCOPE_SESSION .and. &
                    ctx%symbols(j)%value%kind == VK_CONCEPT) then
                    if (associated(ctx%symbols(j)%value%obj, refs(k)%ptr)) then
                        call append_string(gone, ctx%symbols(j)%name)
                        forgotten = ctx%delete_symbol(ctx%symbols(j)%name, SCOPE_SESSION)
                    end if
                end if
                j = min(j - 1, ctx%nsymbol)
            end do
        end do
        names = ''
        do k = 1, size(gone)
            if (k > 1) names = names // ', '
            names = names // gone(k)%s
        end do
        if (len(names) == 0) names = '(no name)'
        call ctx%write_mess('    -> forgotten: ' // names)
    end subroutine run_detruire

end module session_commands
