!> The MED server: the child process in which every call of the MED library (and so of
!> HDF5) on a file runs, one server per open file (med_file starts it at med_open and ends it
!> at med_close). What HDF5 may do on a damaged file (free a bad pointer, run off an array)
!> or after a failed write (leave a state its exit handlers trip on) then happens in that
!> process, never in parasol's: the parent sees the server's socket close, learns from the
!> exit status how it died, and reports one line naming the file (doc/stability.md,
!> "Faults"). HDF5's and MED's own messages go nowhere (the child's stderr is /dev/null).
!>
!> Protocol (byte_message over the child_process socket): a request is an operation code
!> (OP_*) and its inputs in the order listed at each case of `serve_one`; the reply is the
!> entry point's result code (0 or a count on success, < 0 on failure), errno after a
!> failed call (0 when the failure came from no system call), then the outputs. The server
!> keeps the MED file id; it ends after replying to OP_CLOSE, or when its socket closes.
module med_server
    use, intrinsic :: iso_c_binding, only: c_int, c_int64_t, c_double, c_char, c_null_char
    use kinds, only: dp, i4
    use byte_message, only: message_t
    use child_process, only: send_message, receive_message, end_child
    use system_error, only: last_errno, clear_errno
    use med_plugin, only: plugin, fp_state_t, fp_begin, PLUGIN_BAD_SIZE
    use med_import, only: convert_to_current, import_copy_path
    implicit none
    private

    integer, parameter, public :: OP_COMPATIBILITY = 1, OP_OPEN = 2, OP_FILE_VERSION = 3, &
        OP_CLOSE = 4, OP_MESH_COUNT = 5, OP_MESH_INFO = 6, OP_MESH_STEP = 7, OP_COUNT = 8, &
        OP_CELL_TYPE = 9, OP_READ_COORDINATES = 10, OP_READ_CONNECTIVITY = 11, &
        OP_READ_NAMES = 12, OP_READ_FAMILIES = 13, OP_FAMILY_COUNT = 14, &
        OP_FAMILY_GROUP_COUNT = 15, OP_FAMILY_INFO = 16, OP_CREATE_MESH = 17, &
        OP_WRITE_COORDINATES = 18, OP_WRITE_CONNECTIVITY = 19, OP_WRITE_NAMES = 20, &
        OP_WRITE_FAMILIES = 21, OP_CREATE_FAMILY = 22, OP_FIELD_COUNT = 23, &
        OP_FIELD_INFO = 24, OP_CREATE_FIELD = 25, OP_PROFILE_COUNT = 26, &
        OP_WRITE_PROFILE = 27, OP_WRITE_FIELD_VALUES = 28, OP_LOCALIZATION_COUNT = 29, &
        OP_LOCALIZATION_NAME = 30, OP_WRITE_LOCALIZATION = 31, OP_WRITE_ENTITY_VALUES = 32, &
        OP_FIELD_STEP_COUNT = 33, OP_FIELD_STEP_INFO = 34, OP_FIELD_PART_COUNT = 35, &
        OP_FIELD_PART_INFO = 36, OP_READ_ENTITY_VALUES = 37, OP_READ_PROFILE = 38, &
        OP_IMPORT = 39
    !> Returned for a request the server does not know (a bug: client and server disagree).
    integer(c_int), parameter, public :: SERVER_BAD_REQUEST = -900100

    !> Bytes of the fixed name buffers (med.h sizes plus the NUL).
    integer, parameter :: NAME_BYTES = 64 + 1

    public :: serve_med

contains

    !> The server loop, run in the child process right after it is started; never returns.
    !> Floating-point traps are off for good here (MED and HDF5 are not written for them).
    !>  fd : in, the child's end of the socket pair
    subroutine serve_med(fd)
        integer(c_int), intent(in) :: fd
        type(message_t) :: request, reply
        type(fp_state_t) :: fp
        integer(c_int64_t) :: fid
        integer :: op
        logical :: ok, done
        call fp_begin(fp)
        fid = -1
        do
            call receive_message(fd, request, ok)
            if (.not. ok) exit
            op = request%get_int()
            call reply%clear()
            call serve_one(op, request, reply, fid, done)
            call send_message(fd, reply, ok)
            if (.not. ok .or. done) exit
        end do
        call end_child(0)
    end subroutine serve_med

    !> Runs one request. done: the file was closed (the server ends).
    subroutine serve_one(op, q, r, fid, done)
        integer, intent(in) :: op
        type(message_t), intent(inout) :: q, r
        integer(c_int64_t), intent(inout) :: fid
        logical, intent(out) :: done
        character(len=:), allocatable :: a, b, c
        character(kind=c_char), allocatable :: chars(:), more(:), names(:)
        character(kind=c_char) :: name(NAME_BYTES), other(NAME_BYTES)
        integer(i4), allocatable :: ints(:)
        real(dp), allocatable :: reals(:), more_reals(:), weights(:)
        real(dp) :: x
        integer(c_int) :: rc, i1, i2, i3, i4_, i5, i6, n
        integer :: err, ios
        done = .false.
        call clear_errno()
        select case (op)
        case (OP_COMPATIBILITY)                       ! path
            a = q%get_text()
            rc = plugin%compatibility(a // c_null_char, i1, i2)
            call head(r, rc)
            call r%put_int(int(i1))
            call r%put_int(int(i2))
        case (OP_OPEN)                                ! path, mode
            a = q%get_text()
            i1 = q%get_int()
            rc = plugin%open(a // c_null_char, i1, fid)
            call head(r, rc)
        case (OP_FILE_VERSION)
            rc = plugin%file_version(fid, i1, i2, i3)
            call head(r, rc)
            call r%put_int(int(i1))
            call r%put_int(int(i2))
            call r%put_int(int(i3))
        case (OP_IMPORT)                              ! path, folder (med_import)
            ! A 2.x file: closed, converted into the folder by MEDimport, the copy opened
            ! for reading (mode 0, MED_READ) and its version read. Replies the stage that
            ! failed (1 converting, 2 opening the copy), the reason, the copy's version.
            a = q%get_text()
            b = q%get_text()
            if (fid >= 0) rc = plugin%close(fid)
            fid = -1
            i1 = -1; i2 = -1; i3 = -1; i4_ = 1
            rc = convert_to_current(a, b, c)
            if (rc >= 0) then
                i4_ = 2
                rc = plugin%open(import_copy_path(b) // c_null_char, 0_c_int, fid)
                if (rc >= 0) rc = plugin%file_version(fid, i1, i2, i3)
            end if
            call head(r, rc)
            call r%put_int(int(i4_))
            call r%put_text(c)
            call r%put_int(int(i1))
            call r%put_int(int(i2))
            call r%put_int(int(i3))
        case (OP_CLOSE)
            rc = plugin%close(fid)
            call head(r, rc)
            done = .true.
        case (OP_MESH_COUNT)
            call head(r, plugin%mesh_count(fid))
        case (OP_MESH_INFO)                           ! it
            i1 = q%get_int()
            name = c_null_char
            rc = plugin%mesh_info(fid, i1, name, i2, i3, i4_, i5)
            call head(r, rc)
            call r%put_chars(name)
            call r%put_int(int(i2))
            call r%put_int(int(i3))
            call r%put_int(int(i4_))
            call r%put_int(int(i5))
        case (OP_MESH_STEP)                           ! mesh, it
            a = q%get_text()
            i1 = q%get_int()
            rc = plugin%mesh_step(fid, a // c_null_char, i1, i2, i3)
            call head(r, rc)
            call r%put_int(int(i2))
            call r%put_int(int(i3))
        case (OP_COUNT)                               ! mesh, numdt, numit, what, geotype
            a = q%get_text()
            i1 = q%get_int(); i2 = q%get_int(); i3 = q%get_int(); i4_ = q%get_int()
            call head(r, plugin%count(fid, a // c_null_char, i1, i2, i3, i4_))
        case (OP_CELL_TYPE)                           ! mesh, numdt, numit, it
            a = q%get_text()
            i1 = q%get_int(); i2 = q%get_int(); i3 = q%get_int()
            rc = plugin%cell_type(fid, a // c_null_char, i1, i2, i3, i4_)
            call head(r, rc)
            call r%put_int(int(i4_))
        case (OP_READ_COORDINATES)                    ! mesh, numdt, numit, size
            a = q%get_text()
            i1 = q%get_int(); i2 = q%get_int(); n = q%get_int()
            allocate (reals(max(n, 0)), stat=ios)
            rc = PLUGIN_BAD_SIZE
            if (ios == 0) rc = plugin%read_coordinates(fid, a // c_null_char, i1, i2, reals)
            call head(r, rc)
            if (rc >= 0) call r%put_reals(reals)
        case (OP_READ_CONNECTIVITY)                   ! mesh, numdt, numit, geotype, size
            a = q%get_text()
            i1 = q%get_int(); i2 = q%get_int(); i3 = q%get_int(); n = q%get_int()
            allocate (ints(max(n, 0)), stat=ios)
            rc = PLUGIN_BAD_SIZE
            if (ios == 0) rc = plugin%read_connectivity(fid, a // c_null_char, i1, i2, i3, ints)
            call head(r, rc)
            if (rc >= 0) call r%put_ints(ints)
        case (OP_READ_NAMES)                 ! mesh, numdt, numit, entity, geotype, bytes
            a = q%get_text()
            i1 = q%get_int(); i2 = q%get_int(); i3 = q%get_int(); i4_ = q%get_int()
            n = q%get_int()
            allocate (chars(max(n, 1)), stat=ios)
            rc = PLUGIN_BAD_SIZE
            if (ios == 0) then
                chars = c_null_char
                rc = plugin%read_names(fid, a // c_null_char, i1, i2, i3, i4_, chars)
            end if
            call head(r, rc)
            if (rc >= 0) call r%put_chars(chars)
        case (OP_READ_FAMILIES)              ! mesh, numdt, numit, entity, geotype, size
            a = q%get_text()
            i1 = q%get_int(); i2 = q%get_int(); i3 = q%get_int(); i4_ = q%get_int()
            n = q%get_int()
            allocate (ints(max(n, 0)), stat=ios)
            rc = PLUGIN_BAD_SIZE
            if (ios == 0) rc = plugin%read_families(fid, a // c_null_char, i1, i2, i3, i4_, ints)
            call head(r, rc)
            if (rc >= 0) call r%put_ints(ints)
        case (OP_FAMILY_COUNT)                        ! mesh
            a = q%get_text()
            call head(r, plugin%family_count(fid, a // c_null_char))
        case (OP_FAMILY_GROUP_COUNT)                  ! mesh, it
            a = q%get_text()
            i1 = q%get_int()
            call head(r, plugin%family_group_count(fid, a // c_null_char, i1))
        case (OP_FAMILY_INFO)                         ! mesh, it, capacity (groups)
            a = q%get_text()
            i1 = q%get_int(); i2 = q%get_int()
            allocate (chars(80 * max(i2, 1) + 1), stat=ios)
            rc = PLUGIN_BAD_SIZE
            name = c_null_char
            if (ios == 0) then
                chars = c_null_char
                rc = plugin%family_info(fid, a // c_null_char, i1, i2, name, i3, chars)
            end if
            call head(r, rc)
            call r%put_chars(name)
            call r%put_int(int(i3))
            if (rc >= 0) call r%put_chars(chars)
        case (OP_CREATE_MESH)                         ! mesh, spacedim, description
            a = q%get_text()
            i1 = q%get_int()
            b = q%get_text()
            call head(r, plugin%create_mesh(fid, a // c_null_char, i1, b // c_null_char))
        case (OP_WRITE_COORDINATES)                   ! mesh, n, values
            a = q%get_text()
            i1 = q%get_int()
            call q%get_reals(reals)
            call head(r, plugin%write_coordinates(fid, a // c_null_char, i1, reals))
        case (OP_WRITE_CONNECTIVITY)                  ! mesh, geotype, n, values
            a = q%get_text()
            i1 = q%get_int(); i2 = q%get_int()
            call q%get_ints(ints)
            call head(r, plugin%write_connectivity(fid, a // c_null_char, i1, i2, ints))
        case (OP_WRITE_NAMES)                         ! mesh, entity, geotype, n, names
            a = q%get_text()
            i1 = q%get_int(); i2 = q%get_int(); i3 = q%get_int()
            call q%get_chars(chars)
            call head(r, plugin%write_names(fid, a // c_null_char, i1, i2, i3, chars))
        case (OP_WRITE_FAMILIES)                      ! mesh, entity, geotype, numbers
            a = q%get_text()
            i1 = q%get_int(); i2 = q%get_int()
            call q%get_ints(ints)
            call head(r, plugin%write_families(fid, a // c_null_char, i1, i2, &
                                               int(size(ints), c_int), ints))
        case (OP_CREATE_FAMILY)                       ! mesh, name, number, ngroups, groups
            a = q%get_text()
            b = q%get_text()
            i1 = q%get_int(); i2 = q%get_int()
            call q%get_chars(chars)
            call head(r, plugin%create_family(fid, a // c_null_char, b // c_null_char, i1, &
                                              i2, chars))
        case (OP_FIELD_COUNT)
            call head(r, plugin%field_count(fid))
        case (OP_FIELD_INFO)                          ! it, capacity (components)
            i1 = q%get_int(); i2 = q%get_int()
            allocate (chars(16 * max(i2, 1) + 1))
            chars = c_null_char
            name = c_null_char
            other = c_null_char
            rc = plugin%field_info(fid, i1, i2, name, other, i3, chars)
            call head(r, rc)
            call r%put_chars(name)
            call r%put_chars(other)
            call r%put_int(int(i3))
            call r%put_chars(chars)
        case (OP_CREATE_FIELD)                 ! field, mesh, ncomponent, names, units
            a = q%get_text()
            b = q%get_text()
            i1 = q%get_int()
            call q%get_chars(names)
            call q%get_chars(more)
            call head(r, plugin%create_field(fid, a // c_null_char, b // c_null_char, i1, &
                                             names, more))
        case (OP_PROFILE_COUNT)
            call head(r, plugin%profile_count(fid))
        case (OP_WRITE_PROFILE)                       ! name, numbers
            a = q%get_text()
            call q%get_ints(ints)
            call head(r, plugin%write_profile(fid, a // c_null_char, int(size(ints), c_int), &
                                              ints))
        case (OP_WRITE_FIELD_VALUES)       ! field, numdt, numit, dt, n, profile, values
            a = q%get_text()
            i1 = q%get_int(); i2 = q%get_int()
            x = q%get_real()
            i3 = q%get_int()
            c = q%get_text()
            call q%get_reals(reals)
            call head(r, plugin%write_field_values(fid, a // c_null_char, i1, i2, &
                                                   real(x, c_double), i3, c // c_null_char, &
                                                   reals))
        case (OP_LOCALIZATION_COUNT)
            call head(r, plugin%localization_count(fid))
        case (OP_LOCALIZATION_NAME)                   ! it
            i1 = q%get_int()
            name = c_null_char
            rc = plugin%localization_name(fid, i1, name)
            call head(r, rc)
            call r%put_chars(name)
        case (OP_WRITE_LOCALIZATION)     ! name, geotype, dim, refcoo, npoints, gscoo, weights
            a = q%get_text()
            i1 = q%get_int(); i2 = q%get_int()
            call q%get_reals(reals)
            i3 = q%get_int()
            call q%get_reals(more_reals)
            call q%get_reals(weights)
            call head(r, plugin%write_localization(fid, a // c_null_char, i1, i2, reals, i3, &
                                                   more_reals, weights))
        case (OP_WRITE_ENTITY_VALUES)   ! field, numdt, numit, dt, entity, geotype, n,
            a = q%get_text()            ! profile, localisation, values
            i1 = q%get_int(); i2 = q%get_int()
            x = q%get_real()
            i3 = q%get_int(); i4_ = q%get_int(); i5 = q%get_int()
            b = q%get_text()
            c = q%get_text()
            call q%get_reals(reals)
            call head(r, plugin%write_entity_values(fid, a // c_null_char, i1, i2, &
                real(x, c_double), i3, i4_, i5, b // c_null_char, c // c_null_char, reals))
        case (OP_FIELD_STEP_COUNT)                    ! field
            a = q%get_text()
            call head(r, plugin%field_step_count(fid, a // c_null_char))
        case (OP_FIELD_STEP_INFO)                     ! field, it
            a = q%get_text()
            i1 = q%get_int()
            rc = plugin%field_step_info(fid, a // c_null_char, i1, i2, i3, x)
            call head(r, rc)
            call r%put_int(int(i2))
            call r%put_int(int(i3))
            call r%put_real(real(x, dp))
        case (OP_FIELD_PART_COUNT)             ! field, numdt, numit, entity, geotype
            a = q%get_text()
            i1 = q%get_int(); i2 = q%get_int(); i3 = q%get_int(); i4_ = q%get_int()
            call head(r, plugin%field_profile_count(fid, a // c_null_char, i1, i2, i3, i4_))
        case (OP_FIELD_PART_INFO)          ! field, numdt, numit, entity, geotype, it
            a = q%get_text()
            i1 = q%get_int(); i2 = q%get_int(); i3 = q%get_int(); i4_ = q%get_int()
            i5 = q%get_int()
            name = c_null_char
            other = c_null_char
            rc = plugin%field_value_info(fid, a // c_null_char, i1, i2, i3, i4_, i5, name, n, &
                                         other, i6)
            call head(r, rc)
            call r%put_chars(name)
            call r%put_chars(other)
            call r%put_int(int(i6))
        case (OP_READ_ENTITY_VALUES)   ! field, numdt, numit, entity, geotype, profile, size
            a = q%get_text()
            i1 = q%get_int(); i2 = q%get_int(); i3 = q%get_int(); i4_ = q%get_int()
            b = q%get_text()
            n = q%get_int()
            allocate (reals(max(n, 0)), stat=ios)
            rc = PLUGIN_BAD_SIZE
            if (ios == 0) rc = plugin%read_entity_values(fid, a // c_null_char, i1, i2, i3, &
                                                         i4_, b // c_null_char, n, reals)
            call head(r, rc)
            if (rc >= 0) call r%put_reals(reals)
        case (OP_READ_PROFILE)                        ! name, capacity
            a = q%get_text()
            n = q%get_int()
            allocate (ints(max(n, 1)), stat=ios)
            rc = PLUGIN_BAD_SIZE
            if (ios == 0) rc = plugin%read_profile(fid, a // c_null_char, n, ints)
            call head(r, rc)
            if (rc >= 0) call r%put_ints(ints(1:rc))
        case default
            call head(r, SERVER_BAD_REQUEST)
        end select
        if (q%bad) then          ! a request shorter than its operation needs: a bug
            call r%clear()
            call head(r, SERVER_BAD_REQUEST)
        end if
    contains
        ! The reply's head: the result code and, after a failure, errno.
        subroutine head(reply, code)
            type(message_t), intent(inout) :: reply
            integer(c_int), intent(in) :: code
            err = 0
            if (code < 0) err = last_errno()
            call reply%put_int(int(code))
            call reply%put_int(err)
        end subroutine head
    end subroutine serve_one

end module med_server
