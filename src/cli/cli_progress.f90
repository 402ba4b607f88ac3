!> What the user sees of a run's progress on standard output (the progress_t reporter that
!> cli gives the run context; --quiet gives a silent_progress_t instead).
!>  - notes (a finished time step, an analysis starting) are lines that stay, printed at
!>    once;
!>  - work under way (update) is shown only once it has lasted SHOW_AFTER seconds: on a
!>    terminal one line redrawn in place with a carriage return, at most every
!>    TERMINAL_REFRESH seconds; when standard output is not a terminal (a pipe, a log
!>    file) plain lines, at most one every PLAIN_INTERVAL seconds, so a log stays short.
!> Whether standard output is a terminal is asked of the C library (isatty(1)).
module cli_progress
    use, intrinsic :: iso_fortran_env, only: output_unit
    use, intrinsic :: iso_c_binding, only: c_int
    use kinds, only: dp
    use strings, only: to_text
    use progress, only: progress_t, wall_seconds
    implicit none
    private

    !> Work shorter than this (s) is never shown: small decks print only their notes.
    real(dp), parameter :: SHOW_AFTER = 1.0_dp
    !> Shortest time (s) between two redraws of the in-place line on a terminal.
    real(dp), parameter :: TERMINAL_REFRESH = 0.1_dp
    !> Shortest time (s) between two plain progress lines when not on a terminal.
    real(dp), parameter :: PLAIN_INTERVAL = 5.0_dp
    !> The in-place line is cut to this many characters (an 80-column terminal does not
    !> wrap it, so the carriage return still goes back to its start).
    integer, parameter :: LINE_WIDTH = 79

    !> The terminal reporter.
    type, extends(progress_t), public :: terminal_progress_t
        logical :: terminal = .false.   !< standard output is a terminal
        integer :: unit = output_unit
        logical :: working = .false.    !< an update is under way
        real(dp) :: started = 0.0_dp    !< when the work under way started
        real(dp) :: last_shown = 0.0_dp !< when it was last shown
        logical :: shown = .false.      !< it has been shown at least once
        integer :: width = 0            !< characters of the in-place line on screen now
    contains
        procedure :: note => terminal_note
        procedure :: update => terminal_update
        procedure :: done => terminal_done
    end type terminal_progress_t

    interface
        function c_isatty(fd) result(yes) bind(c, name='isatty')
            import :: c_int
            integer(c_int), value :: fd
            integer(c_int) :: yes
        end function c_isatty
    end interface

    public :: stdout_is_terminal, progress_line

contains

    !> True when standard output (file descriptor 1) is a terminal.
    logical function stdout_is_terminal()
        stdout_is_terminal = c_isatty(1_c_int) == 1_c_int
    end function stdout_is_terminal

    !> A note: the in-place line (if any) is wiped, then the note printed on its own line.
    subroutine terminal_note(self, text)
        class(terminal_progress_t), intent(inout) :: self
        character(len=*), intent(in) :: text
        call wipe(self)
        write (self%unit, '(a)') text
        flush (self%unit)
    end subroutine terminal_note

    !> Work under way (see the module header for when it is shown).
    subroutine terminal_update(self, text, fraction)
        class(terminal_progress_t), intent(inout) :: self
        character(len=*), intent(in) :: text
        real(dp), intent(in), optional :: fraction
        real(dp) :: now
        character(len=:), allocatable :: line
        now = wall_seconds()
        if (.not. self%working) then
            self%working = .true.
            self%started = now
            self%shown = .false.
        end if
        if (now - self%started < SHOW_AFTER) return
        if (self%shown) then
            if (self%terminal .and. now - self%last_shown < TERMINAL_REFRESH) return
            if (.not. self%terminal .and. now - self%last_shown < PLAIN_INTERVAL) return
        end if
        line = text
        if (allocated(self%context)) then
            if (len(self%context) > 0) line = self%context // ': ' // text
        end if
        if (present(fraction)) then
            line = progress_line(line, now - self%started, fraction)
        else
            line = progress_line(line, now - self%started)
        end if
        if (self%terminal) then
            if (len(line) > LINE_WIDTH) line = line(1:LINE_WIDTH)
            write (self%unit, '(a)', advance='no') achar(13) // line // &
                repeat(' ', max(self%width - len(line), 0))
            self%width = len(line)
        else
            write (self%unit, '(a)') line
        end if
        flush (self%unit)
        self%shown = .true.
        self%last_shown = now
    end subroutine terminal_update

    !> The work is over: its in-place line is wiped.
    subroutine terminal_done(self)
        class(terminal_progress_t), intent(inout) :: self
        call wipe(self)
        self%working = .false.
        self%shown = .false.
    end subroutine terminal_done

    !> Removes the in-place line from a terminal (blanks over it, cursor back at its start).
    subroutine wipe(self)
        class(terminal_progress_t), intent(inout) :: self
        if (.not. self%terminal .or. self%width == 0) return
        write (self%unit, '(a)', advance='no') achar(13) // repeat(' ', self%width) // &
            achar(13)
        flush (self%unit)
        self%width = 0
    end subroutine wipe

    !> The text of a progress line: `text [NN%] (elapsed S s)`.
    !>  text : in, what is being done;  elapsed : in, seconds since the work started
    !>  fraction : in, optional, how far (0..1); shown as a whole percentage
    function progress_line(text, elapsed, fraction) result(line)
        character(len=*), intent(in) :: text
        real(dp), intent(in) :: elapsed
        real(dp), intent(in), optional :: fraction
        character(len=:), allocatable :: line
        character(len=16) :: buf
        line = text
        if (present(fraction)) then
            if (fraction >= 0.0_dp .and. fraction <= 1.0_dp) line = line // ' ' // &
                to_text(int(100.0_dp * fraction)) // '%'
        end if
        write (buf, '(f0.1)') max(elapsed, 0.0_dp)
        if (buf(1:1) == '.') buf = '0' // buf(1:len(buf) - 1)
        line = line // ' (' // trim(buf) // ' s)'
    end function progress_line

end module cli_progress
