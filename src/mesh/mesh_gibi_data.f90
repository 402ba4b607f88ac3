!> What a GIBI file (Cast3M's SAUVER format) holds as mesh_gibi_reader reads it, and the
!> tables of Cast3M's element types (gilio2) with Code_Aster's names and node orders
!> (giecma, giinco), shared by the reader and the .mail writer (mesh_gibi_writer).
module mesh_gibi_data
    use kinds, only: dp, i4
    implicit none
    private

    public :: N_TYPES, GIBI_CODES, GIBI_NAMES, ASTER_NAMES, TYPE_NODES, N_PARASOL_TYPES
    public :: MAX_TYPE_NODES, PERM, KNOWN_LEVELS, object_t, gibi_t
    public :: per_line, width, objects_written, usable_name, is_internal

    !> Cast3M's element types (gilio2) and Code_Aster's names (giecma) and node orders
    !> (giinco: Code_Aster's node k is Cast3M's node PERM(k)).
    integer(i4), parameter :: N_TYPES = 17
    integer(i4), parameter :: GIBI_CODES(N_TYPES) = [1, 2, 3, 4, 6, 8, 10, 11, 14, 15, 33, &
        16, 17, 23, 24, 25, 26]
    character(len=4), parameter :: GIBI_NAMES(N_TYPES) = ['POI1', 'SEG2', 'SEG3', 'TRI3', &
        'TRI6', 'QUA4', 'QUA8', 'QUA9', 'CUB8', 'CU20', 'CU27', 'PRI6', 'PR15', 'TET4', &
        'TE10', 'PYR5', 'PY13']
    character(len=7), parameter :: ASTER_NAMES(N_TYPES) = ['POI1   ', 'SEG2   ', 'SEG3   ', &
        'TRIA3  ', 'TRIA6  ', 'QUAD4  ', 'QUAD8  ', 'QUAD9  ', 'HEXA8  ', 'HEXA20 ', 'HEXA27 ', &
        'PENTA6 ', 'PENTA15', 'TETRA4 ', 'TETRA10', 'PYRAM5 ', 'PYRAM13']
    integer(i4), parameter :: TYPE_NODES(N_TYPES) = [1, 2, 3, 3, 6, 4, 8, 9, 8, 20, 27, 6, &
        15, 4, 10, 5, 13]
    !> The types parasol's meshes hold (the first 8).
    integer(i4), parameter :: N_PARASOL_TYPES = 8
    integer(i4), parameter :: MAX_TYPE_NODES = 27
    integer(i4), parameter :: PERM(MAX_TYPE_NODES, N_TYPES) = reshape([ &
        1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &   ! POI1
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &
        1, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &   ! SEG2
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &
        1, 3, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &   ! SEG3
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &
        1, 2, 3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &   ! TRI3
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &
        1, 3, 5, 2, 4, 6, 0, 0, 0, 0, 0, 0, 0, 0, &   ! TRI6
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &
        1, 2, 3, 4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &   ! QUA4
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &
        1, 3, 5, 7, 2, 4, 6, 8, 0, 0, 0, 0, 0, 0, &   ! QUA8
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &
        1, 3, 5, 7, 2, 4, 6, 8, 9, 0, 0, 0, 0, 0, &   ! QUA9
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &
        1, 2, 3, 4, 5, 6, 7, 8, 0, 0, 0, 0, 0, 0, &   ! CUB8
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &
        1, 3, 5, 7, 13, 15, 17, 19, 2, 4, 6, 8, 9, 10, &   ! CU20
        11, 12, 14, 16, 18, 20, 0, 0, 0, 0, 0, 0, 0, &
        1, 3, 5, 7, 13, 15, 17, 19, 2, 4, 6, 8, 9, 10, &   ! CU27
        11, 12, 14, 16, 18, 20, 25, 21, 22, 23, 24, 26, 27, &
        1, 2, 3, 4, 5, 6, 0, 0, 0, 0, 0, 0, 0, 0, &   ! PRI6
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &
        1, 3, 5, 10, 12, 14, 2, 4, 6, 7, 8, 9, 11, 13, &   ! PR15
        15, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &
        1, 2, 3, 4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &   ! TET4
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &
        1, 3, 5, 10, 2, 4, 6, 7, 8, 9, 0, 0, 0, 0, &   ! TE10
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &
        1, 2, 3, 4, 5, 0, 0, 0, 0, 0, 0, 0, 0, 0, &   ! PYR5
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, &
        1, 3, 5, 7, 13, 2, 4, 6, 8, 9, 10, 11, 12, 0, &   ! PY13
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0], [MAX_TYPE_NODES, N_TYPES])
    !> The levels (NIVEAU) Code_Aster knows; others are read with a warning (PREPOST3_76).
    integer(i4), parameter :: KNOWN_LEVELS(9) = [3, 4, 5, 6, 8, 9, 10, 11, 13]

    !> One object of pile 1 (a MAILLAGE: cells of one type, or a list of such objects).
    type :: object_t
        integer(i4) :: kind = 0          !< index in the type tables; 0: composite
        integer(i4) :: n_nodes = 0, n_cells = 0
        integer(i4), allocatable :: sub(:)      !< sub-objects (composite)
        integer(i4), allocatable :: points(:)   !< (n_nodes * n_cells) point numbers
        integer(i4) :: line = 0                 !< its header line
        integer(i4) :: points_line = 0          !< the first line of its points
    end type object_t

    !> What the file holds, as read.
    type :: gibi_t
        integer(i4) :: dim = 0, level = 0
        type(object_t), allocatable :: objects(:)
        character(len=8), allocatable :: object_names(:)
        integer(i4), allocatable :: named_objects(:)
        character(len=8), allocatable :: point_names(:)
        integer(i4), allocatable :: named_points(:)   !< the points they name
        logical :: has_indirection = .false.
        integer(i4), allocatable :: indirection(:)    !< node of each point
        real(dp), allocatable :: coords(:, :)         !< (dim, nodes)
        integer(i4) :: pile1_line = 0, points_line = 0, named_points_line = 0
        integer(i4) :: coords_line = 0               !< first line of the reals
        integer(i4) :: last_line = 0
    end type gibi_t

contains

    pure integer(i4) function per_line(g)
        type(gibi_t), intent(in) :: g
        per_line = merge(16_i4, 10_i4, g%level == 3)
    end function per_line

    pure integer(i4) function width(g)
        type(gibi_t), intent(in) :: g
        width = merge(5_i4, 8_i4, g%level == 3)
    end function width

    ! The objects whose cells are written: the named ones and their sub-objects.
    function objects_written(g) result(written)
        type(gibi_t), intent(in) :: g
        logical, allocatable :: written(:)
        integer(i4) :: i, j
        allocate (written(size(g%objects)), source=.false.)
        do i = 1, size(g%named_objects)
            j = g%named_objects(i)
            written(j) = .true.
            if (g%objects(j)%kind == 0) written(g%objects(j)%sub) = .true.
        end do
    end function objects_written

    ! A name the .mail can give a group (Cast3M's own, starting with #, are not written).
    logical function usable_name(name)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: s
        integer :: k
        s = trim(adjustl(name))
        usable_name = len(s) > 0
        if (.not. usable_name .or. is_internal(s)) return
        do k = 1, len(s)
            if (index(' ,%' // achar(9) // achar(13), s(k:k)) > 0) usable_name = .false.
        end do
    end function usable_name

    ! Cast3M's own names start with #: not written (giecas).
    logical function is_internal(name)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: s
        s = adjustl(name)
        is_internal = .false.
        if (len_trim(s) > 0) is_internal = s(1:1) == '#'
    end function is_internal

end module mesh_gibi_data
