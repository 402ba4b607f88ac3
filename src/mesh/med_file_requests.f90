!> The requests of med_file: one request and its reply exchanged with the MED server, the
!> messages of a failed operation (a MED error, a damaged file, a server that died), and the
!> conversions the requests share: names to fixed-width character buffers and back,
!> signaling NaNs of a reply made quiet.
submodule (med_file) med_file_requests
    implicit none

contains

    module procedure exchange
        integer :: err
        logical :: ok, checking
        checking = .true.
        if (present(check)) checking = check
        rc = -1
        if (.not. associated(file%link)) then
            call set_error(st, STATUS_INTERNAL, 'MED file ' // file%path // ' is not open')
            return
        end if
        if (file%link%lost) then
            call server_died(st, file, verb, object)
            return
        end if
        call send_message(file%link%server%fd, q, ok)
        if (ok) call receive_message(file%link%server%fd, r, ok)
        if (.not. ok) then
            call reap_child(file%link%server)
            file%link%lost = .true.
            file%link%lost_how = child_end_text(file%link%server)
            call server_died(st, file, verb, object)
            return
        end if
        rc = r%get_int()
        err = r%get_int()
        if (r%bad) then
            call set_error(st, STATUS_INTERNAL, 'MED file ' // file%path // ': the MED ' // &
                'server gave a short reply (a bug: please report it)')
            rc = -1
            return
        end if
        if (rc < 0 .and. checking) call fail(st, file, verb, object, rc, err, writing)
    end procedure exchange

    module procedure server_died
        character(len=:), allocatable :: doing
        select case (verb)
        case ('read', 'count', 'open')
            doing = verb // 'ing'
        case ('write', 'create', 'close')
            doing = verb(1:len(verb) - 1) // 'ing'
        case default
            doing = 'asked to ' // verb
        end select
        if (file%mode == MED_READ) then
            call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ' is damaged: ' &
                // 'the MED library died ' // doing // ' ' // object // ' (' // &
                file%link%lost_how // ')')
        else
            call set_error(st, STATUS_IO_ERROR, 'cannot write ' // file%path // ': the MED ' &
                // 'library died ' // doing // ' ' // object // ' (' // file%link%lost_how &
                // ')')
        end if
    end procedure server_died

    module procedure fail
        logical :: written
        written = file%mode /= MED_READ
        if (present(writing)) written = writing
        if (written) then
            select case (err)
            case (EIO, EFBIG, ENOSPC, EROFS, EDQUOT)
                call set_error(st, STATUS_IO_ERROR, 'cannot write ' // file%path // ': ' // &
                    errno_text(err) // ' (MED could not ' // verb // ' ' // object // ')')
            case default
                call set_error(st, STATUS_IO_ERROR, 'cannot write ' // file%path // ': MED ' &
                    // 'could not ' // verb // ' ' // object // ' (MED error ' // &
                    to_text(int(rc, i4)) // ')')
            end select
        else if (rc == PLUGIN_BAD_SIZE) then
            call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': cannot ' // &
                verb // ' ' // object // ' (it holds more than parasol expects)')
        else
            call set_error(st, STATUS_MESH_ERROR, 'MED file ' // file%path // ': cannot ' // &
                verb // ' ' // object // ' (MED error ' // to_text(int(rc, i4)) // &
                '; the file is damaged, truncated or inconsistent)')
        end if
    end procedure fail

    module procedure quiet_signaling_nans
        integer(i8), parameter :: EXPONENT = int(z'7FF0000000000000', i8), &
            MANTISSA = int(z'000FFFFFFFFFFFFF', i8), QUIET = int(z'0008000000000000', i8)
        integer(i8) :: bits
        integer :: k
        do k = 1, size(values)
            bits = transfer(values(k), bits)
            if (iand(bits, EXPONENT) == EXPONENT .and. iand(bits, MANTISSA) /= 0 .and. &
                iand(bits, QUIET) == 0) values(k) = transfer(ior(bits, QUIET), values(k))
        end do
    end procedure quiet_signaling_nans

    module procedure fixed_chars
        integer :: k, j
        allocate (buffer(width * size(names) + 1))
        do k = 1, size(names)
            do j = 1, width
                buffer((k - 1) * width + j) = names(k)(j:j)
            end do
        end do
        buffer(size(buffer)) = c_null_char
    end procedure fixed_chars

    module procedure buffer_text
        integer :: k, n
        n = 0
        do k = start, min(start + length - 1, size(buffer))
            if (buffer(k) == c_null_char) exit
            n = n + 1
        end do
        text = repeat(' ', n)
        do k = 1, n
            text(k:k) = buffer(start + k - 1)
        end do
        text = trim(text)
    end procedure buffer_text

end submodule med_file_requests
