!> DEBUT and FIN: start and end of a deck. Their Code_Aster bookkeeping keywords (CODE,
!> DEBUG, PAR_LOT, FORMAT_HDF, ...) are accepted by the catalog and have no effect.
!> FIN marks the deck finished (a later command is an error) and closes the listings: the
!> run pipeline (cli) then writes the verdict and commits .mess and .resu.
module session_commands
    use status, only: status_t
    use deck_concept, only: concept_t
    use deck_command, only: command_t
    use run_context, only: run_context_t
    implicit none
    private
    public :: run_debut, run_fin

contains

    !> DEBUT(): writes the start of the run to the .mess.
    subroutine run_debut(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        if (allocated(result)) deallocate (result)     ! DEBUT has no result
        if (cmd%n < 0) return
        call ctx%write_mess('    -> start of the deck ' // ctx%deck_name)
    end subroutine run_debut

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
