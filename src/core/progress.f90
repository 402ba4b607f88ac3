!> Progress of a run, told to whoever runs parasol. The layers that do long work (the
!> analyses, IMPR_RESU) never write to the terminal: they call a reporter passed to them
!> (run_context%progress) and cli decides what the user sees (cli_progress: lines on a
!> terminal, rate-limited plain lines in a log, nothing with --quiet).
!>
!> Two kinds of report:
!>  - note   : a line of its own that stays (a finished time step, an analysis starting);
!>  - update : work under way (what, and how far when known); shown only when the work
!>             lasts, redrawn in place on a terminal. `done` ends it.
!> Times come from one monotonic wall clock (wall_seconds), the one the Newton table's TIME
!> column uses too (doc/analysis.md).
module progress
    use kinds, only: dp, i8
    implicit none
    private

    !> What a reporter does with the reports (cli implements it).
    type, abstract, public :: progress_t
        !> What the updates are part of (e.g. 'STAT_NON_LINE, INST 1.0, iteration 2'); a
        !> reporter shows it before the text of each update (progress_context sets it).
        character(len=:), allocatable :: context
    contains
        procedure(note_interface), deferred :: note
        procedure(update_interface), deferred :: update
        procedure(done_interface), deferred :: done
    end type progress_t

    abstract interface
        !> A line that stays: a finished step, an analysis starting.
        !>  text : in, the line (no newline)
        subroutine note_interface(self, text)
            import :: progress_t
            class(progress_t), intent(inout) :: self
            character(len=*), intent(in) :: text
        end subroutine note_interface
        !> Work under way.
        !>  text     : in, what is being done (e.g. 'INST 1.0, iteration 2: factorization')
        !>  fraction : in, optional, how far (0..1) when known
        subroutine update_interface(self, text, fraction)
            import :: progress_t, dp
            class(progress_t), intent(inout) :: self
            character(len=*), intent(in) :: text
            real(dp), intent(in), optional :: fraction
        end subroutine update_interface
        !> The work described by update is over.
        subroutine done_interface(self)
            import :: progress_t
            class(progress_t), intent(inout) :: self
        end subroutine done_interface
    end interface

    !> The reporter that shows nothing (--quiet): it only counts what it is told, and keeps
    !> the last note (unit tests read them).
    type, extends(progress_t), public :: silent_progress_t
        integer :: notes = 0, updates = 0, dones = 0
        character(len=:), allocatable :: last_note
    contains
        procedure :: note => silent_note
        procedure :: update => silent_update
        procedure :: done => silent_done
    end type silent_progress_t

    public :: wall_seconds, progress_note, progress_update, progress_done, progress_context

contains

    !> Seconds on the monotonic wall clock (system_clock with 64-bit counts: nanosecond
    !> resolution in gfortran); only differences mean anything.
    function wall_seconds() result(seconds)
        real(dp) :: seconds
        integer(i8) :: count, rate
        call system_clock(count, rate)
        seconds = real(count, dp) / real(max(rate, 1_i8), dp)
    end function wall_seconds

    !> note() through a reporter that may be absent (not associated): then nothing.
    subroutine progress_note(reporter, text)
        class(progress_t), pointer, intent(in) :: reporter
        character(len=*), intent(in) :: text
        if (associated(reporter)) call reporter%note(text)
    end subroutine progress_note

    !> update() through a reporter that may be absent.
    subroutine progress_update(reporter, text, fraction)
        class(progress_t), pointer, intent(in) :: reporter
        character(len=*), intent(in) :: text
        real(dp), intent(in), optional :: fraction
        if (.not. associated(reporter)) return
        if (present(fraction)) then
            call reporter%update(text, fraction)
        else
            call reporter%update(text)
        end if
    end subroutine progress_update

    !> Sets what the following updates are part of ('' = nothing), on a reporter that may
    !> be absent.
    subroutine progress_context(reporter, text)
        class(progress_t), pointer, intent(in) :: reporter
        character(len=*), intent(in) :: text
        if (associated(reporter)) reporter%context = text
    end subroutine progress_context

    !> done() through a reporter that may be absent.
    subroutine progress_done(reporter)
        class(progress_t), pointer, intent(in) :: reporter
        if (associated(reporter)) call reporter%done()
    end subroutine progress_done

    subroutine silent_note(self, text)
        class(silent_progress_t), intent(inout) :: self
        character(len=*), intent(in) :: text
        self%notes = self%notes + 1
        self%last_note = text
    end subroutine silent_note

    subroutine silent_update(self, text, fraction)
        class(silent_progress_t), intent(inout) :: self
        character(len=*), intent(in) :: text
        real(dp), intent(in), optional :: fraction
        if (len(text) >= 0 .or. present(fraction)) self%updates = self%updates + 1
    end subroutine silent_update

    subroutine silent_done(self)
        class(silent_progress_t), intent(inout) :: self
        self%dones = self%dones + 1
    end subroutine silent_done

end module progress
