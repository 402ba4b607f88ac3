!> Child processes that run work a crash must not take parasol down with it: third-party
!> code that may corrupt memory or die on a damaged input (the MED library and HDF5 on a
!> damaged file, src/mesh/med_server.f90). The child is a fork(2) of parasol, so it has the
!> data and the loaded libraries already; the two talk through a socket pair with framed
!> messages (byte_message), sent with MSG_NOSIGNAL so that a peer that died is an error, not
!> a SIGPIPE. The parent learns how a child ended (an exit status, or the signal that killed
!> it) when it reaps it.
!>
!> A child ends with `end_child` (_exit(2)): no exit handlers, no Fortran unit flushed, no
!> library's atexit cleanup, so nothing of the parent's state is written or torn down twice.
!> Its standard error goes to /dev/null: what a library prints while it fails is not
!> parasol's message (the parent reports one line of its own).
module child_process
    use, intrinsic :: iso_c_binding, only: c_int, c_char, c_long, c_size_t, c_int64_t, &
        c_null_char
    use kinds, only: i4, i8
    use status, only: status_t, set_error, STATUS_IO_ERROR
    use strings, only: to_text
    use system_error, only: last_errno, errno_text
    use byte_message, only: message_t
    implicit none
    private

    type, public :: child_t
        integer(c_int) :: pid = -1
        integer(c_int) :: fd = -1          !< this side's end of the socket pair
        logical :: reaped = .false.
        integer :: exit_status = -1        !< when it exited (reaped)
        integer :: signal = 0              !< the signal that killed it (reaped), 0 if none
    end type child_t

    public :: start_child, end_child, send_message, receive_message, reap_child, &
        child_end_text

    !> Sockets of the children running, closed in each new child (so that a child's end of
    !> the pair is held by its parent alone, and it sees the parent go).
    integer, parameter :: MAX_CHILDREN = 16
    integer(c_int), save :: child_fds(MAX_CHILDREN) = -1

    integer(c_int), parameter :: AF_UNIX = 1, SOCK_STREAM = 1, MSG_NOSIGNAL = int(z'4000')
    integer, parameter :: EINTR = 4
    !> Largest message accepted (1 TiB: a sanity bound on a length read from the peer).
    integer(i8), parameter :: MAX_MESSAGE_BYTES = 2_i8**40

    interface
        function c_socketpair(domain, type, protocol, sv) result(rc) bind(c, name='socketpair')
            import :: c_int
            integer(c_int), value :: domain, type, protocol
            integer(c_int), intent(out) :: sv(2)
            integer(c_int) :: rc
        end function c_socketpair
        function c_prctl(option, arg2) result(rc) bind(c, name='prctl')
            import :: c_int, c_long
            integer(c_int), value :: option
            integer(c_long), value :: arg2
            integer(c_int) :: rc
        end function c_prctl
        function c_getpid_here() result(pid) bind(c, name='getpid')
            import :: c_int
            integer(c_int) :: pid
        end function c_getpid_here
        function c_getppid() result(pid) bind(c, name='getppid')
            import :: c_int
            integer(c_int) :: pid
        end function c_getppid
        function c_fork() result(pid) bind(c, name='fork')
            import :: c_int
            integer(c_int) :: pid
        end function c_fork
        function c_waitpid(pid, wstatus, options) result(rc) bind(c, name='waitpid')
            import :: c_int
            integer(c_int), value :: pid, options
            integer(c_int), intent(out) :: wstatus
            integer(c_int) :: rc
        end function c_waitpid
        subroutine c_exit_now(code) bind(c, name='_exit')
            import :: c_int
            integer(c_int), value :: code
        end subroutine c_exit_now
        function c_send(fd, buf, n, flags) result(sent) bind(c, name='send')
            import :: c_int, c_char, c_size_t, c_long
            integer(c_int), value :: fd, flags
            character(kind=c_char), intent(in) :: buf(*)
            integer(c_size_t), value :: n
            integer(c_long) :: sent
        end function c_send
        function c_recv(fd, buf, n, flags) result(got) bind(c, name='recv')
            import :: c_int, c_char, c_size_t, c_long
            integer(c_int), value :: fd, flags
            character(kind=c_char), intent(out) :: buf(*)
            integer(c_size_t), value :: n
            integer(c_long) :: got
        end function c_recv
        function c_close(fd) result(rc) bind(c, name='close')
            import :: c_int
            integer(c_int), value :: fd
            integer(c_int) :: rc
        end function c_close
        function c_open(pathname, flags) result(fd) bind(c, name='open')
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: pathname(*)
            integer(c_int), value :: flags
            integer(c_int) :: fd
        end function c_open
        function c_dup2(old, new) result(fd) bind(c, name='dup2')
            import :: c_int
            integer(c_int), value :: old, new
            integer(c_int) :: fd
        end function c_dup2
    end interface

contains

    !> Forks a child connected to this process by a socket pair. Returns twice: in the
    !> parent with in_child = .false. (child%pid, child%fd: the parent's end), and in the
    !> child with in_child = .true. (child%fd: the child's end), which must end with
    !> end_child.
    !>  what : in, what the child is for (messages)
    !>  st   : out, STATUS_IO_ERROR when the socket pair or the process cannot be made
    subroutine start_child(child, in_child, what, st)
        type(child_t), intent(out) :: child
        logical, intent(out) :: in_child
        character(len=*), intent(in) :: what
        type(status_t), intent(out) :: st
        integer(c_int) :: sv(2), pid, rc, null, parent
        integer(c_int), parameter :: PR_SET_PDEATHSIG = 1
        integer :: k, code
        integer(c_int), parameter :: O_WRONLY = 1, STDERR = 2
        in_child = .false.
        if (c_socketpair(AF_UNIX, SOCK_STREAM, 0_c_int, sv) /= 0) then
            code = last_errno()
            call set_error(st, STATUS_IO_ERROR, 'cannot start the process that ' // what // &
                ': ' // errno_text(code))
            return
        end if
        parent = c_getpid_here()
        pid = c_fork()
        if (pid < 0) then
            code = last_errno()
            rc = c_close(sv(1))
            rc = c_close(sv(2))
            call set_error(st, STATUS_IO_ERROR, 'cannot start the process that ' // what // &
                ': ' // errno_text(code))
            return
        end if
        if (pid == 0) then
            in_child = .true.
            ! The child ends with parasol (SIGKILL when its parent dies, Linux prctl(2)
            ! PR_SET_PDEATHSIG): a library call that never returns (MEDimport looping on a
            ! damaged file) never outlives a run that was stopped.
            rc = c_prctl(PR_SET_PDEATHSIG, 9_c_long)
            if (c_getppid() /= parent) call c_exit_now(1_c_int)
            rc = c_close(sv(1))
            do k = 1, MAX_CHILDREN
                if (child_fds(k) >= 0) rc = c_close(child_fds(k))
                child_fds(k) = -1
            end do
            child%fd = sv(2)
            null = c_open('/dev/null' // c_null_char, O_WRONLY)
            if (null >= 0) then
                rc = c_dup2(null, STDERR)
                rc = c_close(null)
            end if
            return
        end if
        rc = c_close(sv(2))
        child%pid = pid
        child%fd = sv(1)
        do k = 1, MAX_CHILDREN
            if (child_fds(k) < 0) then
                child_fds(k) = child%fd
                exit
            end if
        end do
    end subroutine start_child

    !> Ends the child process at once with exit status `code` (_exit: nothing of the
    !> parent's state is flushed or cleaned up here).
    subroutine end_child(code)
        integer, intent(in) :: code
        call c_exit_now(int(code, c_int))
    end subroutine end_child

    !> Sends `message` whole (its length first). ok = .false. when the peer is gone.
    subroutine send_message(fd, message, ok)
        integer(c_int), intent(in) :: fd
        type(message_t), intent(in) :: message
        logical, intent(out) :: ok
        character(kind=c_char) :: header(8), mold(1)
        header = transfer(int(message%length, c_int64_t), mold, 8)
        call send_all(fd, header, 8_i8, ok)
        if (ok .and. message%length > 0) call send_all(fd, message%bytes, message%length, ok)
    end subroutine send_message

    ! send(2) of the first n bytes of buf, going on after partial sends and interruptions.
    subroutine send_all(fd, buf, n, ok)
        integer(c_int), intent(in) :: fd
        character(kind=c_char), intent(in) :: buf(:)
        integer(i8), intent(in) :: n
        logical, intent(out) :: ok
        integer(i8) :: done
        integer(c_long) :: sent
        done = 0
        ok = .true.
        do while (done < n)
            sent = c_send(fd, buf(done + 1:), int(n - done, c_size_t), MSG_NOSIGNAL)
            if (sent < 0) then
                if (last_errno() == EINTR) cycle
            end if
            if (sent <= 0) then
                ok = .false.
                return
            end if
            done = done + sent
        end do
    end subroutine send_all

    !> Receives one message whole. ok = .false. when the peer is gone (or sent a length
    !> beyond MAX_MESSAGE_BYTES).
    subroutine receive_message(fd, message, ok)
        integer(c_int), intent(in) :: fd
        type(message_t), intent(inout) :: message
        logical, intent(out) :: ok
        character(kind=c_char) :: header(8)
        integer(c_int64_t) :: n
        call message%clear()
        call receive_all(fd, header, 8_i8, ok)
        if (.not. ok) return
        n = transfer(header, n)
        ok = n >= 0 .and. n <= MAX_MESSAGE_BYTES
        if (.not. ok) return
        if (allocated(message%bytes)) then
            if (size(message%bytes, kind=i8) < n) deallocate (message%bytes)
        end if
        if (.not. allocated(message%bytes)) allocate (message%bytes(max(n, 1_c_int64_t)))
        if (n > 0) call receive_all(fd, message%bytes, int(n, i8), ok)
        if (ok) message%length = n
    end subroutine receive_message

    ! recv(2) of exactly n bytes into buf; ok = .false. on end of stream or error.
    subroutine receive_all(fd, buf, n, ok)
        integer(c_int), intent(in) :: fd
        character(kind=c_char), intent(inout) :: buf(:)
        integer(i8), intent(in) :: n
        logical, intent(out) :: ok
        integer(i8) :: done
        integer(c_long) :: got
        done = 0
        ok = .true.
        do while (done < n)
            got = c_recv(fd, buf(done + 1:), int(n - done, c_size_t), 0_c_int)
            if (got < 0) then
                if (last_errno() == EINTR) cycle
            end if
            if (got <= 0) then
                ok = .false.
                return
            end if
            done = done + got
        end do
    end subroutine receive_all

    !> Closes the parent's end and waits for the child to end (a child that serves until
    !> its socket closes ends then); records its exit status or the signal that killed it.
    !> Reaping twice is a no-op.
    subroutine reap_child(child)
        type(child_t), intent(inout) :: child
        integer(c_int) :: rc, wstatus
        integer :: k
        if (child%reaped .or. child%pid <= 0) return
        if (child%fd >= 0) then
            do k = 1, MAX_CHILDREN
                if (child_fds(k) == child%fd) child_fds(k) = -1
            end do
            rc = c_close(child%fd)
            child%fd = -1
        end if
        do
            rc = c_waitpid(child%pid, wstatus, 0_c_int)
            if (rc >= 0) exit
            if (last_errno() /= EINTR) exit
        end do
        child%reaped = .true.
        if (rc < 0) return
        if (iand(wstatus, int(z'7f', c_int)) == 0) then
            child%exit_status = iand(ishft(wstatus, -8), int(z'ff', c_int))
        else
            child%signal = iand(wstatus, int(z'7f', c_int))
        end if
    end subroutine reap_child

    !> How a reaped child ended: "killed by signal 11 (SIGSEGV)", "exit status 3".
    function child_end_text(child) result(text)
        type(child_t), intent(in) :: child
        character(len=:), allocatable :: text
        if (child%signal > 0) then
            text = 'killed by signal ' // to_text(int(child%signal, i4)) // ' (' // &
                signal_name(child%signal) // ')'
        else
            text = 'exit status ' // to_text(int(child%exit_status, i4))
        end if
    end function child_end_text

    ! The usual name of a Linux signal number.
    function signal_name(sig) result(name)
        integer, intent(in) :: sig
        character(len=:), allocatable :: name
        select case (sig)
        case (1); name = 'SIGHUP'
        case (2); name = 'SIGINT'
        case (4); name = 'SIGILL'
        case (6); name = 'SIGABRT'
        case (7); name = 'SIGBUS'
        case (8); name = 'SIGFPE'
        case (9); name = 'SIGKILL'
        case (11); name = 'SIGSEGV'
        case (13); name = 'SIGPIPE'
        case (14); name = 'SIGALRM'
        case (15); name = 'SIGTERM'
        case (24); name = 'SIGXCPU'
        case (25); name = 'SIGXFSZ'
        case default; name = 'signal ' // to_text(int(sig, i4))
        end select
    end function signal_name

end module child_process
