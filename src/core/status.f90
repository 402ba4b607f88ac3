!> Error status carried from where a failure is found up to the command level.
!>
!> A procedure that can fail takes `type(status_t), intent(out) :: st`. On failure it calls
!> `set_error` with a category code and a message saying what is wrong and what would be
!> right; callers add what they know (file/line/column, command, keyword) with `add_context`
!> and return. The command dispatcher reports the status; only `cli` turns it into an exit
!> status. Messages are formatted as design.md requires:
!>     deck.comm:LINE:COL: error: COMMAND/KEYWORD: what is wrong (and what would be right)
module status
    use kinds, only: i4
    implicit none
    private

    !> Categories of failure (the `code` of a status_t). 0 means success.
    integer, parameter, public :: STATUS_OK = 0
    integer, parameter, public :: STATUS_DECK_ERROR = 1       !< syntax, catalog, evaluation
    integer, parameter, public :: STATUS_MESH_ERROR = 2       !< mesh file contents
    integer, parameter, public :: STATUS_MODEL_ERROR = 3      !< model, materials, loads
    integer, parameter, public :: STATUS_SINGULAR = 4         !< singular matrix (NPREC)
    integer, parameter, public :: STATUS_NO_CONVERGENCE = 5   !< Newton / contact iteration
    integer, parameter, public :: STATUS_IO_ERROR = 6         !< files and units
    integer, parameter, public :: STATUS_NOT_IMPLEMENTED = 7  !< valid input, not built yet
    integer, parameter, public :: STATUS_NO_EQUILIBRIUM = 8   !< rigid motion left free
    integer, parameter, public :: STATUS_INTERNAL = 9         !< a bug: should never happen

    type, public :: status_t
        integer(i4) :: code = STATUS_OK
        character(len=:), allocatable :: message   !< what is wrong and what would be right
        character(len=:), allocatable :: file      !< deck or mesh file, if known
        integer(i4) :: line = 0                    !< 1-based, 0 if unknown
        integer(i4) :: column = 0                  !< 1-based, 0 if unknown
        character(len=:), allocatable :: command   !< e.g. AFFE_CARA_ELEM
        character(len=:), allocatable :: keyword   !< e.g. RIGI_PARASOL/VALE
    contains
        procedure :: ok => status_is_ok
        procedure :: failed => status_has_failed
    end type status_t

    public :: set_error, add_context, format_status, clear_status

contains

    !> True when no error was recorded.
    elemental logical function status_is_ok(self)
        class(status_t), intent(in) :: self
        status_is_ok = self%code == STATUS_OK
    end function status_is_ok

    !> True when an error was recorded.
    elemental logical function status_has_failed(self)
        class(status_t), intent(in) :: self
        status_has_failed = self%code /= STATUS_OK
    end function status_has_failed

    !> Resets `st` to success.
    subroutine clear_status(st)
        type(status_t), intent(out) :: st
        st%code = STATUS_OK
    end subroutine clear_status

    !> Records a failure.
    !>  st      : out, the status to fill
    !>  code    : in, one of the STATUS_* categories (not STATUS_OK)
    !>  message : in, what is wrong and, where possible, what would be right
    !>  file, line, column, command, keyword : in, optional location of the failure
    subroutine set_error(st, code, message, file, line, column, command, keyword)
        type(status_t), intent(inout) :: st
        integer, intent(in) :: code
        character(len=*), intent(in) :: message
        character(len=*), intent(in), optional :: file, command, keyword
        integer, intent(in), optional :: line, column
        st%code = code
        st%message = message
        if (present(file)) st%file = file
        if (present(line)) st%line = line
        if (present(column)) st%column = column
        if (present(command)) st%command = command
        if (present(keyword)) st%keyword = keyword
    end subroutine set_error

    !> Adds location or command context to a failed status, keeping what is already known
    !> (the innermost, most precise location wins).
    subroutine add_context(st, file, line, column, command, keyword)
        type(status_t), intent(inout) :: st
        character(len=*), intent(in), optional :: file, command, keyword
        integer, intent(in), optional :: line, column
        if (st%ok()) return
        if (present(file)) then
            if (.not. allocated(st%file)) st%file = file
        end if
        if (present(line)) then
            if (st%line == 0) then
                st%line = line
                if (present(column)) st%column = column
            end if
        end if
        if (present(command)) then
            if (.not. allocated(st%command)) st%command = command
        end if
        if (present(keyword)) then
            if (.not. allocated(st%keyword)) st%keyword = keyword
        end if
    end subroutine add_context

    !> The one-line message `file:line:col: error: COMMAND/KEYWORD: message`; parts that are
    !> unknown are left out.
    function format_status(st) result(text)
        type(status_t), intent(in) :: st
        character(len=:), allocatable :: text
        character(len=16) :: buf
        text = ''
        if (allocated(st%file)) then
            text = st%file // ':'
            if (st%line > 0) then
                write (buf, '(i0)') st%line
                text = text // trim(buf) // ':'
                if (st%column > 0) then
                    write (buf, '(i0)') st%column
                    text = text // trim(buf) // ':'
                end if
            end if
            text = text // ' '
        end if
        text = text // 'error: '
        if (allocated(st%command)) then
            text = text // st%command
            if (allocated(st%keyword)) text = text // '/' // st%keyword
            text = text // ': '
        else if (allocated(st%keyword)) then
            text = text // st%keyword // ': '
        end if
        if (allocated(st%message)) then
            text = text // st%message
        else
            text = text // 'unspecified failure'
        end if
    end function format_status

end module status
