!> DEBUT, POURSUITE and FIN: start, continuation and end of a command file. Their
!> Code_Aster bookkeeping keywords (CODE, DEBUG, PAR_LOT, FORMAT_HDF, ...) are accepted by
!> the catalog and have no effect.
!> FIN marks the file finished (a later command is an error); after the last file the run
!> pipeline (cli) writes the verdict and commits .mess and .resu. In a session of several
!> command files (an export file), POURSUITE() makes the names of the earlier files
!> defined again, as Code_Aster's POURSUITE restores the database the previous file saved;
!> DEBUT() in a later file starts a new session instead. Both also run in the check pass
!> (at_check), so that the check pass sees the same names as the run.
module session_commands
    use kinds, only: i4
    use strings, only: to_text
    use status, only: status_t, set_error, STATUS_DECK_ERROR
    use deck_concept, only: concept_t
    use deck_command, only: command_t
    use run_context, only: run_context_t
    implicit none
    private
    public :: run_debut, run_poursuite, run_fin

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

end module session_commands
