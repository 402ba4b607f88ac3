!> The parasol command line (design.md, "How people use it"): options, then the deck.
!> Only this layer decides the exit status:
!>   0 = ran, every TEST_RESU OK (or none); 2 = ran, some TEST_RESU NOOK;
!>   1 = stopped on an error (deck, mesh, singular matrix, no convergence).
!>
!> Pipeline of a run: read and parse the command files (one deck, several on the command
!> line, or those of a Code_Aster export file, see export_file); check pass over them in
!> order (every expression evaluated, every command validated against the catalog,
!> placeholder concepts); run pass (each command dispatched to its handler). The files
!> form one session: a file after the first continues it with POURSUITE(). <stem>.mess and
!> <stem>.resu are written atomically in --outdir (stem: the first deck's, or the export
!> file's). On an error the message goes to stderr and to the .mess, the .mess is committed
!> (it is the run's story) and the .resu is discarded (an older one is left untouched).
module cli
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use kinds, only: i4, dp
    use strings, only: string_t, to_text, starts_with
    use status, only: status_t, format_status, set_error, add_context, STATUS_DECK_ERROR, &
        STATUS_IO_ERROR
    use system_error, only: readable_errno, errno_text
    use cli_args, only: get_arguments
    use parasol_version, only: parasol_version_string
    use atomic_file, only: open_atomic, install_interrupt_cleanup
    use install_layout, only: data_file_path
    use run_context, only: run_context_t, init_context
    use deck_value, only: append_string
    use deck_interpreter, only: read_source_text, load_source, evaluate_session
    use export_file, only: export_t, read_export, is_export_path, module_name
    use command_registration, only: register_commands
    use progress, only: silent_progress_t, wall_seconds
    use cli_progress, only: terminal_progress_t, stdout_is_terminal
    use mumps_solver, only: mumps_session_t, mumps_session_start, mumps_session_stop
    implicit none
    private
    public :: run_parasol, print_usage, bundled_deck_path

    integer, parameter, public :: EXIT_OK = 0, EXIT_ERROR = 1, EXIT_NOOK = 2

    !> The bundled deck run when no DECK is given, a data file of the build tree or install
    !> (bundled_deck_path). Its mesh is found beside it (the unit 20 default).
    character(len=*), parameter, public :: BUNDLED_DECK = 'ssnl130a.comm'

    !> Parsed command line. decks: the command files, in order (empty: the bundled deck);
    !> export: an export file instead (then decks is empty).
    type :: options_t
        type(string_t), allocatable :: decks(:)
        character(len=:), allocatable :: export, outdir
        logical :: check = .false.
        logical :: quiet = .false.      !< --quiet: nothing on standard output
        logical :: bundled = .false.    !< the bundled deck (its own closing lines)
        integer(i4), allocatable :: units(:)
        type(string_t), allocatable :: unit_paths(:)
    end type options_t

contains

    !> Parses the command line and runs parasol; returns the exit status. In the MPI build
    !> under mpirun, process 0 does all of this and the other processes only serve its
    !> MUMPS factorizations and solves (mumps_session_start), then exit 0 silently.
    subroutine run_parasol(exit_status)
        integer, intent(out) :: exit_status
        type(mumps_session_t) :: session
        type(status_t) :: st
        logical :: worker
        call install_interrupt_cleanup()
        call mumps_session_start(session, worker, st)
        if (st%failed()) then
            write (error_unit, '(a)') 'parasol: error: ' // st%message
            exit_status = EXIT_ERROR
            return
        end if
        exit_status = EXIT_OK
        if (worker) return
        call run_command_line(exit_status)
        call mumps_session_stop(session)
    end subroutine run_parasol

    !> The command line of process 0 (or of the only process).
    subroutine run_command_line(exit_status)
        integer, intent(out) :: exit_status
        type(string_t), allocatable :: args(:)
        type(options_t) :: opts
        logical :: done
        call get_arguments(args)
        call parse_options(args, opts, exit_status, done)
        if (done) return
        if (size(opts%decks) == 0 .and. .not. allocated(opts%export)) then
            call run_bundled(opts, exit_status)
            return
        end if
        call run_deck(opts, exit_status)
    end subroutine run_command_line

    !> No deck on the command line: run the bundled SSNL130 model A deck (the demonstration
    !> and smoke test of an installation), then show its TEST_RESU table on the terminal so
    !> the verdict is visible without opening the .resu. Exit status as for any deck.
    subroutine run_bundled(opts, exit_status)
        type(options_t), intent(inout) :: opts
        integer, intent(out) :: exit_status
        logical :: exists
        character(len=:), allocatable :: deck
        deck = bundled_deck_path()
        inquire (file=deck, exist=exists)
        if (.not. exists) then
            write (error_unit, '(a)') 'parasol: error: no DECK given and the bundled deck ' // &
                deck // ' is missing (give a deck: parasol [options] DECK)'
            call print_usage(error_unit)
            exit_status = EXIT_ERROR
            return
        end if
        call append_string(opts%decks, deck)
        opts%bundled = .true.
        if (.not. opts%quiet) write (output_unit, '(a)') 'parasol ' // &
            parasol_version_string // ': no deck given (usage: parasol [options] [DECK]; ' // &
            'parasol --help), running the bundled SSNL130 model A deck ' // deck
        call run_deck(opts, exit_status)
        if (exit_status /= EXIT_ERROR .and. .not. opts%quiet) &
            call echo_test_resu(opts, exit_status)
    end subroutine run_bundled

    !> Copies the TEST_RESU blocks of the run's .resu (identification lines, table header,
    !> OK/NOOK check lines; listings.md) to standard output, then the verdict line.
    subroutine echo_test_resu(opts, exit_status)
        type(options_t), intent(in) :: opts
        integer, intent(in) :: exit_status
        type(run_context_t) :: ctx
        character(len=1024) :: line
        integer :: u, ios
        logical :: echo_next
        call init_context(ctx, opts%decks(1)%s, opts%outdir)
        open (newunit=u, file=ctx%output_path('.resu'), status='old', action='read', &
              iostat=ios)
        if (ios /= 0) return
        echo_next = .false.
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (echo_next .or. (starts_with(line, ' ---- ') .and. index(line, 'NOM_CMP') > 0) &
                .or. starts_with(line, '      REFERENCE') .or. starts_with(line, ' OK   ') &
                .or. starts_with(line, 'NOOK  ')) then
                write (output_unit, '(a)') trim(line)
            end if
            echo_next = starts_with(line, ' ---- ') .and. index(line, 'NOM_CMP') > 0
        end do
        close (u)
        if (exit_status == EXIT_OK) then
            write (output_unit, '(a)') 'parasol: every TEST_RESU check is OK (listings: ' // &
                ctx%output_path('.mess') // ', ' // ctx%output_path('.resu') // ')'
        else
            write (output_unit, '(a)') 'parasol: some TEST_RESU checks are NOOK (see ' // &
                ctx%output_path('.mess') // ')'
        end if
    end subroutine echo_test_resu

    !> Options: --unit N=PATH, --outdir DIR, --check, --help, --version; the command files
    !> (DECK...) or one export file (CASE.export).
    subroutine parse_options(args, opts, exit_status, done)
        type(string_t), intent(in) :: args(:)
        type(options_t), intent(out) :: opts
        integer, intent(out) :: exit_status
        logical, intent(out) :: done
        integer :: i, eq, unit, ios
        character(len=:), allocatable :: a, value
        exit_status = EXIT_OK; done = .true.
        opts%outdir = ''
        allocate (opts%units(0), opts%unit_paths(0), opts%decks(0))
        i = 1
        do while (i <= size(args))
            a = args(i)%s
            select case (a)
            case ('--help', '-h')
                call print_usage(output_unit); return
            case ('--version')
                write (output_unit, '(a)') 'parasol ' // parasol_version_string; return
            case ('--check')
                opts%check = .true.
            case ('--quiet', '-q')
                opts%quiet = .true.
            case ('--unit', '--outdir')
                if (i == size(args)) then
                    call usage_error('option ' // a // ' needs a value'); return
                end if
                i = i + 1
                value = args(i)%s
                if (a == '--outdir') then
                    opts%outdir = value
                else
                    eq = index(value, '=')
                    unit = -1
                    if (eq > 1) read (value(1:eq - 1), *, iostat=ios) unit
                    if (eq <= 1 .or. ios /= 0 .or. unit < 0 .or. eq == len(value)) then
                        call usage_error('--unit expects N=PATH (e.g. --unit 20=plate.mail), ' &
                                         // 'got "' // value // '"'); return
                    end if
                    opts%units = [opts%units, int(unit, i4)]
                    call append_string(opts%unit_paths, value(eq + 1:))
                end if
            case default
                if (starts_with(a, '-') .and. len(a) > 1) then
                    call usage_error('unknown option ' // a); return
                end if
                if (allocated(opts%export) .or. (is_export_path(a) .and. &
                    size(opts%decks) > 0)) then
                    call usage_error('an export file runs alone: give either CASE.export ' // &
                                     'or the command files (got ' // a // ' too)'); return
                end if
                if (is_export_path(a)) then
                    opts%export = a
                else
                    call append_string(opts%decks, a)
                end if
            end select
            i = i + 1
        end do
        done = .false.
    contains
        subroutine usage_error(message)
            character(len=*), intent(in) :: message
            write (error_unit, '(a)') 'parasol: error: ' // message
            call print_usage(error_unit)
            exit_status = EXIT_ERROR
        end subroutine usage_error
    end subroutine parse_options

    !> Reads, checks and (unless --check) runs the command files: the decks of the
    !> command line, or those of an export file. A file named on the command line that
    !> cannot be opened stops the run before any listing is created. Progress goes to
    !> standard output through the run context's reporter (nothing with --quiet); a run of a
    !> given deck ends with a one-line summary (run_summary).
    subroutine run_deck(opts, exit_status)
        type(options_t), intent(in) :: opts
        integer, intent(out) :: exit_status
        type(run_context_t) :: ctx
        type(export_t) :: exp
        type(status_t) :: st, io
        type(string_t), allocatable :: files(:)
        character(len=:), allocatable :: mess_path, resu_path, header, names
        integer, allocatable :: file_lines(:)
        integer :: k
        real(dp) :: started
        started = wall_seconds()
        if (allocated(opts%export)) then
            call check_readable(opts%export, 'the export file', st)
            names = opts%export
        else
            names = opts%decks(1)%s
            do k = 1, size(opts%decks)
                if (st%ok()) call check_readable(opts%decks(k)%s, 'the deck', st)
                if (k > 1) names = names // ' ' // opts%decks(k)%s
            end do
        end if
        if (st%failed()) then
            write (error_unit, '(a)') error_line(st)
            exit_status = EXIT_ERROR
            return
        end if
        if (allocated(opts%export)) then
            call init_context(ctx, opts%export, opts%outdir)
            call read_export(opts%export, exp, st)
            header = 'export file ' // opts%export
        else
            call init_context(ctx, opts%decks(1)%s, opts%outdir)
            header = 'deck ' // names
        end if
        call start_reporter(ctx, opts%quiet)
        mess_path = ctx%output_path('.mess')
        resu_path = ctx%output_path('.resu')
        if (allocated(opts%export) .and. st%ok()) &
            call apply_export(ctx, exp, files, file_lines, mess_path, resu_path)
        if (allocated(opts%export) .and. st%failed()) call keep_export_mess(exp, mess_path)
        if (.not. allocated(opts%export)) then
            files = opts%decks
            allocate (file_lines(0))
        end if
        do k = 1, size(opts%units)
            call ctx%bind_unit(opts%units(k), opts%unit_paths(k)%s)
        end do
        call register_commands(ctx)
        if (.not. opts%check) then
            call open_atomic(ctx%mess, mess_path, io)
            if (io%ok()) call open_atomic(ctx%resu, resu_path, io)
            if (io%failed()) then
                call ctx%mess%discard()
                call blame_outdir(io%message)
                write (error_unit, '(a)') 'parasol: ' // format_status(io)
                exit_status = EXIT_ERROR
                call stop_reporter(ctx)
                return
            end if
            call ctx%write_mess('parasol ' // parasol_version_string // ' -- ' // header)
            if (allocated(opts%export) .and. st%ok()) call describe_export(ctx, exp)
        end if
        if (st%ok()) then
            if (allocated(opts%export)) then
                call load_command_files(ctx, files, st, opts%export, file_lines)
            else
                call load_command_files(ctx, files, st)
            end if
        end if
        if (st%ok()) call check_pass(ctx, st)
        if (st%ok() .and. opts%check) then
            if (.not. opts%quiet) call say_valid(ctx)
            exit_status = EXIT_OK
            call stop_reporter(ctx)
            call ctx%reset_symbols()
            return
        end if
        if (st%ok()) call run_pass(ctx, st)
        call finish(ctx, st, exit_status)
        if (exit_status /= EXIT_ERROR .and. .not. (opts%quiet .or. opts%bundled)) &
            write (output_unit, '(a)') run_summary(names, ctx%n_ok, ctx%n_nook, mess_path, &
            resu_path, wall_seconds() - started)
        call stop_reporter(ctx)
        call ctx%reset_symbols()
    end subroutine run_deck

    !> --check found the command files valid: one line on standard output.
    ! The listings go to the output folder: when their folder is missing or not writable,
    ! the hint names --outdir (atomic_file names the folder alone).
    subroutine blame_outdir(message)
        character(len=:), allocatable, intent(inout) :: message
        integer :: k
        k = index(message, ' (its folder ', back=.true.)
        if (k == 0) return
        if (index(message(k:), ' does not exist)') > 0) then
            message = message(1:k - 1) // ' (the output folder must exist: create it or ' // &
                'give another --outdir)'
        else if (index(message(k:), ' must be writable)') > 0) then
            message = message(1:k - 1) // ' (the output folder must be writable)'
        end if
    end subroutine blame_outdir

    subroutine say_valid(ctx)
        type(run_context_t), intent(in) :: ctx
        if (ctx%ncommand_file == 1) then
            write (output_unit, '(a)') ctx%sources(1)%name // ': deck is valid (' // &
                to_text(int(ctx%ncommand, i4)) // ' commands checked)'
        else
            write (output_unit, '(a)') to_text(int(ctx%ncommand_file, i4)) // &
                ' command files are valid (' // to_text(int(ctx%ncommand, i4)) // &
                ' commands checked)'
        end if
        if (ctx%check_stopped) write (output_unit, '(a)') check_horizon(ctx)
    end subroutine say_valid

    !> Where a check pass stopped early, in words (doc/deck-language.md, "The check pass").
    function check_horizon(ctx) result(text)
        type(run_context_t), intent(in) :: ctx
        character(len=:), allocatable :: text
        if (allocated(ctx%check_stop_reason)) then
            text = 'checked up to ' // ctx%check_stop_file // ':' // &
                to_text(int(ctx%check_stop_line, i4)) // ': ' // ctx%check_stop_reason // &
                ' (the rest is validated as it runs, each command before it runs)'
            return
        end if
        text = 'checked up to ' // ctx%check_stop_file // ':' // &
            to_text(int(ctx%check_stop_line, i4)) // ': from there the deck depends on ' // &
            'values known when it runs (each command is validated before it runs)'
    end function check_horizon

    !> The line that ends a run of a given deck (not with --quiet): what ran, the TEST_RESU
    !> tally, the listings and the wall time, e.g.
    !> `parasol: plate.comm: 4 TEST_RESU OK, 0 NOOK; listings plate.mess, plate.resu (2.3 s)`.
    !>  names : in, the command files (or export file) as given
    function run_summary(names, n_ok, n_nook, mess_path, resu_path, seconds) result(text)
        character(len=*), intent(in) :: names, mess_path, resu_path
        integer, intent(in) :: n_ok, n_nook
        real(dp), intent(in) :: seconds
        character(len=:), allocatable :: text
        character(len=24) :: buf
        text = 'parasol: ' // names // ': '
        if (n_ok + n_nook == 0) then
            text = text // 'no TEST_RESU'
        else
            text = text // to_text(int(n_ok, i4)) // ' TEST_RESU OK, ' // &
                to_text(int(n_nook, i4)) // ' NOOK'
            if (n_nook > 0) text = text // ' -- SOME TESTS FAILED'
        end if
        write (buf, '(f0.1)') max(seconds, 0.0_dp)
        if (buf(1:1) == '.') buf = '0' // buf(1:len(buf) - 1)
        text = text // '; listings ' // mess_path // ', ' // resu_path // ' (' // trim(buf) // &
            ' s)'
    end function run_summary

    !> Gives the run context its progress reporter: the terminal one (cli_progress), or
    !> with --quiet a silent one.
    subroutine start_reporter(ctx, quiet)
        type(run_context_t), intent(inout) :: ctx
        logical, intent(in) :: quiet
        type(terminal_progress_t), pointer :: screen
        if (quiet) then
            allocate (silent_progress_t :: ctx%progress)
        else
            allocate (screen)
            screen%terminal = stdout_is_terminal()
            ctx%progress => screen
        end if
    end subroutine start_reporter

    !> Ends the reporter (its in-place line wiped) and frees it.
    subroutine stop_reporter(ctx)
        type(run_context_t), intent(inout) :: ctx
        if (.not. associated(ctx%progress)) return
        call ctx%progress%done()
        deallocate (ctx%progress)
    end subroutine stop_reporter

    !> STATUS_IO_ERROR when `path` cannot be opened and read, with the system's reason
    !> (readable_errno), e.g. "cannot open the deck plate.comm: No such file or directory".
    !>  what : in, 'the deck' or 'the export file'
    subroutine check_readable(path, what, st)
        character(len=*), intent(in) :: path, what
        type(status_t), intent(inout) :: st
        integer :: code
        code = readable_errno(path)
        if (code /= 0) call set_error(st, STATUS_IO_ERROR, 'cannot open ' // what // ' ' // &
            path // ': ' // errno_text(code))
    end subroutine check_readable

    !> An error as printed on the terminal: located (`file:line:col: error: ...`), or
    !> `parasol: error: ...` when no file is known.
    function error_line(st) result(text)
        type(status_t), intent(in) :: st
        character(len=:), allocatable :: text
        text = format_status(st)
        if (.not. allocated(st%file)) text = 'parasol: ' // text
    end function error_line

    !> Takes from an export file what the run needs: its command files (in order), its
    !> units (every F TYPE NAME D|R U with U > 0, as run_aster makes it fort.U),
    !> its modules (F nom), its listings (F mess|resu NAME R U) and its time limit.
    !>  files : out, the command files;  file_lines : out, their F comm lines
    subroutine apply_export(ctx, exp, files, file_lines, mess_path, resu_path)
        type(run_context_t), intent(inout) :: ctx
        type(export_t), intent(in) :: exp
        type(string_t), allocatable, intent(out) :: files(:)
        integer, allocatable, intent(out) :: file_lines(:)
        character(len=:), allocatable, intent(inout) :: mess_path, resu_path
        integer :: k
        allocate (files(0), file_lines(0))
        do k = 1, size(exp%entries)
            associate (e => exp%entries(k))
                if (e%folder) cycle
                select case (e%type)
                case ('comm')
                    call append_string(files, e%path)
                    file_lines = [file_lines, e%line]
                case ('nom')
                    call ctx%bind_module(module_name(e%name), e%path)
                case ('mess', 'resu')
                    if (e%result .and. e%type == 'mess') mess_path = e%path
                    if (e%result .and. e%type == 'resu') resu_path = e%path
                case default            ! any other file on a unit, as run_aster's fort.U
                    if (e%unit > 0) call ctx%bind_unit(e%unit, e%path)
                end select
            end associate
        end do
        if (exp%time_limit > 0.0_dp) call ctx%deadline%start(exp%time_limit, &
            exp%path // ':' // to_text(int(exp%time_limit_line, i4)) // ' (P time_limit)')
    end subroutine apply_export

    !> An export file that failed its checks still gets its .mess where its F mess line
    !> puts it, when that line itself is sound (export_result_problem): the error is then
    !> written where the user looks for it, never lost.
    subroutine keep_export_mess(exp, mess_path)
        type(export_t), intent(in) :: exp
        character(len=:), allocatable, intent(inout) :: mess_path
        integer :: k
        if (.not. allocated(exp%entries)) return
        do k = 1, size(exp%entries)
            associate (e => exp%entries(k))
                if (e%folder .or. .not. e%result .or. e%type /= 'mess') cycle
                if (len(exp%result_problem(k)) == 0) mess_path = e%path
            end associate
        end do
    end subroutine keep_export_mess

    !> Records in the .mess each line of the export file and what parasol does with it.
    subroutine describe_export(ctx, exp)
        type(run_context_t), intent(inout) :: ctx
        type(export_t), intent(in) :: exp
        integer :: k
        do k = 1, size(exp%params)
            associate (p => exp%params(k))
                if (p%kind == 'P' .and. p%name == 'time_limit') then
                    call ctx%write_mess('  P time_limit ' // p%value // ' (line ' // &
                        to_text(int(p%line, i4)) // '): wall-clock limit of the run, in s')
                else
                    ! the value quoted as written: parasol does not read it (a "NaN" here
                    ! is the file's text, not a number parasol computed)
                    call ctx%write_mess('  ' // p%kind // ' ' // p%name // ' "' // p%value // &
                        '" (line ' // to_text(int(p%line, i4)) // '): recorded, no effect ' // &
                        'in parasol')
                end if
            end associate
        end do
        do k = 1, size(exp%entries)
            call ctx%write_mess('  ' // exp%describe(k))
        end do
    end subroutine describe_export

    !> Reads and parses each command file; they form the session, in this order.
    !>  export, lines : optional, the export file and the F comm line of each file: a file
    !>  that cannot be read is located there
    subroutine load_command_files(ctx, files, st, export, lines)
        type(run_context_t), intent(inout) :: ctx
        type(string_t), intent(in) :: files(:)
        type(status_t), intent(inout) :: st
        character(len=*), intent(in), optional :: export
        integer, intent(in), optional :: lines(:)
        character(len=:), allocatable :: text
        integer :: k, src, slash
        do k = 1, size(files)
            call read_source_text(files(k)%s, 'the deck', text, st)
            if (st%failed() .and. present(export) .and. present(lines)) &
                call add_context(st, file=export, line=lines(k))
            if (st%failed()) return
            slash = index(files(k)%s, '/', back=.true.)
            call load_source(ctx, text, files(k)%s, files(k)%s(1:slash), '', src, st)
            if (st%failed()) return
        end do
        ctx%ncommand_file = size(files)
    end subroutine load_command_files

    subroutine check_pass(ctx, st)
        type(run_context_t), intent(inout) :: ctx
        type(status_t), intent(inout) :: st
        ctx%checking = .true.
        call evaluate_session(ctx, st)
        ctx%checking = .false.
        if (st%failed()) return
        call ctx%write_mess('check pass: the deck is valid (' // &
                            to_text(int(ctx%ncommand, i4)) // ' commands)')
        if (ctx%check_stopped) call ctx%write_mess('check pass: ' // check_horizon(ctx))
    end subroutine check_pass

    subroutine run_pass(ctx, st)
        type(run_context_t), intent(inout) :: ctx
        type(status_t), intent(inout) :: st
        call ctx%reset_symbols()
        ctx%ncommand = 0
        ctx%echoed = 0
        call evaluate_session(ctx, st)
        if (st%ok() .and. .not. ctx%finished) call ctx%write_mess('warning: ' // &
            ctx%deck_name // ' has no FIN(); the listings are closed at its end')
    end subroutine run_pass

    !> Ends the run's listings and reports. The .resu is published only by a run that ends
    !> well and when all of it reached the disk; a run that fails (deck error, a listing or
    !> result file that could not be written) discards it, so an older .resu of that name
    !> stays as it was. The .mess, which tells the run's story and its error, is published
    !> only when it was written whole; the error line goes to standard error in any case,
    !> and names the .mess too when that could not be written (one line, e.g.
    !> `parasol: error: cannot write OUT/plate.resu: No space left on device`).
    subroutine finish(ctx, run_status, exit_status)
        type(run_context_t), intent(inout) :: ctx
        type(status_t), intent(in) :: run_status
        integer, intent(out) :: exit_status
        type(status_t) :: st, io
        character(len=:), allocatable :: verdict, line
        if (associated(ctx%progress)) call ctx%progress%done()   ! wipe a progress line
        st = run_status
        call ctx%resu%flush()      ! every line handed to the system: a full disk shows here
        if (st%ok() .and. ctx%resu%failed()) &
            call set_error(st, STATUS_IO_ERROR, ctx%resu%error_message())
        if (st%ok() .and. ctx%mess%failed()) &
            call set_error(st, STATUS_IO_ERROR, ctx%mess%error_message())
        if (st%ok()) call ctx%resu%commit(st)
        if (st%failed()) then
            call ctx%resu%discard()
            call ctx%write_mess('')
            call ctx%write_mess(format_status(st))
            call ctx%write_mess('verdict: STOPPED ON AN ERROR after ' // &
                to_text(int(ctx%ncommand, i4)) // ' commands; TEST_RESU: ' // &
                to_text(int(ctx%n_ok, i4)) // ' OK, ' // to_text(int(ctx%n_nook, i4)) // ' NOOK')
            exit_status = EXIT_ERROR
        else
            verdict = 'verdict: ' // to_text(int(ctx%n_ok, i4)) // ' OK, ' // &
                to_text(int(ctx%n_nook, i4)) // ' NOOK'
            exit_status = EXIT_OK
            if (ctx%n_nook > 0) then
                verdict = verdict // ' -- SOME TESTS FAILED'
                exit_status = EXIT_NOOK
            end if
            call ctx%write_mess('')
            call ctx%write_mess(verdict)
        end if
        call ctx%mess%commit(io)
        if (st%ok() .and. io%failed()) then
            st = io
            exit_status = EXIT_ERROR
        end if
        if (st%failed()) then
            line = error_line(st)
            if (io%failed() .and. io%message /= st%message .and. &
                index(st%message, io%message) == 0) line = line // '; ' // io%message
            write (error_unit, '(a)') line
        end if
    end subroutine finish

    !> The bundled deck: BUNDLED_DECK in the data folder of this build tree or install
    !> (install_layout: <source>/decks/ in a build tree, <prefix>/share/parasol/ installed).
    function bundled_deck_path() result(path)
        character(len=:), allocatable :: path
        path = data_file_path(BUNDLED_DECK)
    end function bundled_deck_path

    !> Writes the usage text.
    subroutine print_usage(unit)
        integer, intent(in) :: unit
        write (unit, '(a)') &
            'usage: parasol [options] [DECK [DECK.com1 ...] | CASE.export]', &
            '  DECK               the deck (.comm); without one, parasol runs its bundled', &
            '                     SSNL130 model A deck; several command files run in order', &
            '                     in one session (POURSUITE() continues the previous one)', &
            '  CASE.export        a Code_Aster export file: its F comm files run in order,', &
            '                     its F lines bind units and modules, P time_limit applies', &
            '  --unit N=PATH      bind logical unit N to a file (LIRE_MAILLAGE reads unit 20)', &
            '  --outdir DIR       where <stem>.mess, <stem>.resu and result files go', &
            '  --check            parse and validate the command files, run nothing', &
            '  --quiet, -q        print nothing but errors (no progress, no summary)', &
            '  --help, --version', &
            'exit status: 0 = ran, every TEST_RESU OK; 2 = some TEST_RESU NOOK;', &
            '             1 = stopped on an error'
    end subroutine print_usage

end module cli
