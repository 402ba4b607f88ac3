!> Shared libraries loaded at run time (POSIX dlopen/dlsym), so that a heavy dependency
!> (MED with HDF5 and MPI, a solver back-end) costs nothing to the runs that do not use it:
!> linking such a library into parasol adds its loading time to every process start.
!> A plug-in is opened once with `open_library` and its entry points are looked up with
!> `find_symbol`, then converted with c_f_procpointer to an explicit interface the caller
!> declares. Failures come back as STATUS_IO_ERROR with the loader's own reason (dlerror).
module dynamic_library
    use, intrinsic :: iso_c_binding, only: c_ptr, c_funptr, c_char, c_int, c_null_ptr, &
        c_null_funptr, c_null_char, c_associated
    use status, only: status_t, set_error, STATUS_IO_ERROR
    use system_error, only: c_text
    implicit none
    private

    !> An open shared library (closed with close_library; never closed implicitly, since
    !> procedures taken from it may still be in use).
    type, public :: dynamic_library_t
        character(len=:), allocatable :: path
        type(c_ptr) :: handle = c_null_ptr
    contains
        procedure :: is_open => library_is_open
    end type dynamic_library_t

    public :: open_library, find_symbol, close_library

    !> dlopen flags (<dlfcn.h>, glibc): resolve every symbol now, keep them local.
    integer(c_int), parameter :: RTLD_NOW = 2, RTLD_LOCAL = 0

    interface
        function c_dlopen(filename, flags) result(handle) bind(c, name='dlopen')
            import :: c_ptr, c_char, c_int
            character(kind=c_char), intent(in) :: filename(*)
            integer(c_int), value :: flags
            type(c_ptr) :: handle
        end function c_dlopen
        function c_dlsym(handle, symbol) result(address) bind(c, name='dlsym')
            import :: c_ptr, c_funptr, c_char
            type(c_ptr), value :: handle
            character(kind=c_char), intent(in) :: symbol(*)
            type(c_funptr) :: address
        end function c_dlsym
        function c_dlclose(handle) result(rc) bind(c, name='dlclose')
            import :: c_ptr, c_int
            type(c_ptr), value :: handle
            integer(c_int) :: rc
        end function c_dlclose
        function c_dlerror() result(text) bind(c, name='dlerror')
            import :: c_ptr
            type(c_ptr) :: text
        end function c_dlerror
    end interface

contains

    !> Opens the shared library at `path` (every symbol resolved now).
    !>  lib  : out, the open library
    !>  path : in, the library file
    !>  st   : out, STATUS_IO_ERROR with the loader's reason (missing file, missing
    !>         dependency, wrong architecture ...)
    subroutine open_library(lib, path, st)
        type(dynamic_library_t), intent(out) :: lib
        character(len=*), intent(in) :: path
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: reason
        lib%path = path
        reason = last_error()   ! clears a stale error
        lib%handle = c_dlopen(path // c_null_char, ior(RTLD_NOW, RTLD_LOCAL))
        if (.not. c_associated(lib%handle)) then
            reason = last_error()
            call set_error(st, STATUS_IO_ERROR, 'cannot load the shared library ' // path // &
                ': ' // reason)
        end if
    end subroutine open_library

    !> The address of entry point `name` in `lib`.
    !>  st : out, STATUS_IO_ERROR when the library is not open or lacks the symbol
    subroutine find_symbol(lib, name, address, st)
        type(dynamic_library_t), intent(in) :: lib
        character(len=*), intent(in) :: name
        type(c_funptr), intent(out) :: address
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: reason
        address = c_null_funptr
        if (.not. lib%is_open()) then
            call set_error(st, STATUS_IO_ERROR, 'no shared library open to look up ' // name)
            return
        end if
        reason = last_error()
        address = c_dlsym(lib%handle, name // c_null_char)
        reason = last_error()
        if (len(reason) > 0 .or. .not. c_associated(address)) then
            if (len(reason) == 0) reason = 'null address'
            call set_error(st, STATUS_IO_ERROR, 'the shared library ' // lib%path // &
                ' has no entry point ' // name // ' (' // reason // '); it does not ' // &
                'belong to this version of parasol')
            address = c_null_funptr
        end if
    end subroutine find_symbol

    !> Closes `lib` (procedures taken from it must no longer be called).
    subroutine close_library(lib)
        type(dynamic_library_t), intent(inout) :: lib
        integer(c_int) :: rc
        if (.not. lib%is_open()) return
        rc = c_dlclose(lib%handle)
        lib%handle = c_null_ptr
    end subroutine close_library

    logical function library_is_open(self)
        class(dynamic_library_t), intent(in) :: self
        library_is_open = c_associated(self%handle)
    end function library_is_open

    !> dlerror's text ('' when no error is pending); reading it clears it.
    function last_error() result(text)
        character(len=:), allocatable :: text
        text = c_text(c_dlerror())
    end function last_error

end module dynamic_library
