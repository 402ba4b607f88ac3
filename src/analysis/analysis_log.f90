!> Lines an analysis writes to the .mess: the renumbering summary, the Newton/contact table
!> of each step, warnings. They are kept in order and, once the handler has connected the
!> log to the run's .mess (log_stream), also written there as they come and flushed at the
!> end of each step (log_flush), so that the .mess of a long run grows while it runs.
module analysis_log
    use kinds, only: i4
    use strings, only: string_t
    use atomic_file, only: atomic_file_t
    implicit none
    private

    !> A growing list of lines, optionally written through to an open file.
    type, public :: analysis_log_t
        integer(i4) :: n = 0
        type(string_t), allocatable :: lines(:)
        type(atomic_file_t) :: file                !< where the lines go (if open)
        character(len=:), allocatable :: indent    !< put before each line written there
    end type analysis_log_t

    public :: log_add, log_stream, log_flush

contains

    !> Appends one line (trailing blanks removed), and writes it to the connected file.
    subroutine log_add(log, text)
        type(analysis_log_t), intent(inout) :: log
        character(len=*), intent(in) :: text
        type(string_t), allocatable :: grown(:)
        integer(i4) :: k
        if (.not. allocated(log%lines)) allocate (log%lines(16))
        if (log%n == size(log%lines)) then
            allocate (grown(2 * size(log%lines)))
            do k = 1, log%n
                call move_alloc(log%lines(k)%s, grown(k)%s)
            end do
            call move_alloc(grown, log%lines)
        end if
        log%n = log%n + 1
        log%lines(log%n)%s = trim(text)
        if (log%file%is_open()) call log%file%write_line(log%indent // trim(text))
    end subroutine log_add

    !> Connects the log to an open file: the lines already in it and every later one are
    !> written there, each after `indent` (checked writes: a failure is the file's, reported
    !> when it is committed).
    !>  file : in, the open file (run_context%mess: a second handle to it, used only while
    !>         the analysis runs)
    subroutine log_stream(log, file, indent)
        type(analysis_log_t), intent(inout) :: log
        type(atomic_file_t), intent(in) :: file
        character(len=*), intent(in) :: indent
        integer(i4) :: k
        log%file = file
        log%indent = indent
        if (.not. file%is_open()) return
        do k = 1, log%n
            call file%write_line(indent // log%lines(k)%s)
        end do
    end subroutine log_stream

    !> Hands the lines written so far to the system (a reader of the file sees them).
    subroutine log_flush(log)
        type(analysis_log_t), intent(in) :: log
        call log%file%flush()
    end subroutine log_flush

end module analysis_log
