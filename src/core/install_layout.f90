!> Finds parasol's own files (the bundled deck and its mesh, plug-in libraries) from the
!> real location of the running executable and the layout configured at build time
!> (parasol_layout): an executable in the build tree's output folder uses the build tree's
!> paths; any other location is an install, whose files sit at configured paths relative to
!> its bin/ folder. The executable is located through /proc/self/exe (the kernel's answer),
!> never guessed from argument 0.
module install_layout
    use, intrinsic :: iso_c_binding, only: c_char, c_size_t, c_intptr_t, c_null_char
    use parasol_layout, only: BUILD_BIN_DIR, BUILD_DATA_DIR, BUILD_PLUGIN_DIR, &
        INSTALL_BIN_TO_DATA, INSTALL_BIN_TO_PLUGIN
    implicit none
    private
    public :: executable_dir, data_file_path, plugin_file_path, running_from_build_tree

contains

    !> Folder of the running executable, with a trailing '/', symbolic links resolved
    !> ('' when /proc/self/exe cannot be read).
    function executable_dir() result(dir)
        character(len=:), allocatable :: dir
        integer :: slash
        dir = resolved_link('/proc/self/exe')
        slash = index(dir, '/', back=.true.)
        dir = dir(1:slash)
    end function executable_dir

    !> True when the running executable sits in the build tree's output folder.
    logical function running_from_build_tree()
        running_from_build_tree = same_folder(executable_dir(), BUILD_BIN_DIR)
    end function running_from_build_tree

    !> Path of data file `name` (e.g. 'ssnl130a.comm'): <source>/decks/name in the build
    !> tree, <bin>/INSTALL_BIN_TO_DATA/name in an install.
    function data_file_path(name) result(path)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: path
        if (running_from_build_tree()) then
            path = BUILD_DATA_DIR // '/' // name
        else
            path = executable_dir() // INSTALL_BIN_TO_DATA // '/' // name
        end if
    end function data_file_path

    !> Path of plug-in library `name` (e.g. 'libparasol_med.so'), as data_file_path.
    function plugin_file_path(name) result(path)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: path
        if (running_from_build_tree()) then
            path = BUILD_PLUGIN_DIR // '/' // name
        else
            path = executable_dir() // INSTALL_BIN_TO_PLUGIN // '/' // name
        end if
    end function plugin_file_path

    !> Folders a (with a trailing '/') and b (without) are the same path.
    logical function same_folder(a, b)
        character(len=*), intent(in) :: a, b
        same_folder = len(a) > 0 .and. (a == b .or. a == b // '/')
    end function same_folder

    !> Target of symbolic link `link` (POSIX readlink); '' when it cannot be read.
    function resolved_link(link) result(target)
        character(len=*), intent(in) :: link
        character(len=:), allocatable :: target
        interface
            function c_readlink(pathname, buf, bufsiz) result(n) bind(c, name='readlink')
                import :: c_char, c_size_t, c_intptr_t
                character(kind=c_char), intent(in) :: pathname(*)
                character(kind=c_char), intent(out) :: buf(*)
                integer(c_size_t), value :: bufsiz
                integer(c_intptr_t) :: n  ! ssize_t
            end function c_readlink
        end interface
        integer, parameter :: BUF_LEN = 4096
        character(kind=c_char) :: buf(BUF_LEN)
        integer(c_intptr_t) :: n
        integer :: k
        target = ''
        n = c_readlink(link // c_null_char, buf, int(BUF_LEN, c_size_t))
        if (n <= 0 .or. n >= BUF_LEN) return
        target = repeat(' ', int(n))
        do k = 1, int(n)
            target(k:k) = buf(k)
        end do
    end function resolved_link

end module install_layout
