!> The parasol command line (design.md, "How people use it"): options, then the deck.
!> Only this layer decides the exit status:
!>   0 = ran, every TEST_RESU OK (or none); 2 = ran, some TEST_RESU NOOK;
!>   1 = stopped on an error (deck, mesh, singular matrix, no convergence).
module cli
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use strings, only: string_t
    use cli_args, only: get_arguments
    use parasol_version, only: parasol_version_string
    implicit none
    private
    public :: run_parasol, print_usage

    integer, parameter, public :: EXIT_OK = 0, EXIT_ERROR = 1, EXIT_NOOK = 2

contains

    !> Parses the command line and runs parasol; returns the exit status.
    subroutine run_parasol(exit_status)
        integer, intent(out) :: exit_status
        type(string_t), allocatable :: args(:)
        integer :: i
        call get_arguments(args)
        exit_status = EXIT_OK
        do i = 1, size(args)
            select case (args(i)%s)
            case ('--help', '-h')
                call print_usage(output_unit)
                return
            case ('--version')
                write (output_unit, '(a)') 'parasol ' // parasol_version_string
                return
            end select
        end do
        ! Until decks exist (issue on SSNL130) parasol with no deck prints version and usage.
        write (output_unit, '(a)') 'parasol ' // parasol_version_string
        call print_usage(output_unit)
        if (size(args) > 0) then
            write (error_unit, '(a)') 'parasol: error: running decks is not implemented yet'
            exit_status = EXIT_ERROR
        end if
    end subroutine run_parasol

    !> Writes the usage text.
    subroutine print_usage(unit)
        integer, intent(in) :: unit
        write (unit, '(a)') &
            'usage: parasol [options] [DECK]', &
            '  DECK               the deck (.comm); without one, parasol runs its bundled', &
            '                     SSNL130 model A deck', &
            '  --unit N=PATH      bind logical unit N to a file (LIRE_MAILLAGE reads unit 20)', &
            '  --outdir DIR       where <stem>.mess, <stem>.resu and result files go', &
            '  --check            parse and validate the deck, run nothing', &
            '  --help, --version', &
            'exit status: 0 = ran, every TEST_RESU OK; 2 = some TEST_RESU NOOK;', &
            '             1 = stopped on an error'
    end subroutine print_usage

end module cli
