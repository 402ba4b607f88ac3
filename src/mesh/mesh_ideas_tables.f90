!> The cell kinds of I-DEAS universal files as Code_Aster converts them (PRE_IDEAS: cov4v5
!> maps an FE descriptor to a kind, inistb gives each kind its .mail type, node count and
!> node order). The kinds are numbered as Code_Aster numbers them: the .mail lists the cells
!> kind by kind in this order (ecrelt).
module mesh_ideas_tables
    use kinds, only: i4
    implicit none
    private

    public :: cell_kind, kind_order

    integer(i4), parameter, public :: N_KINDS = 35
    integer(i4), parameter, public :: MAX_KIND_NODES = 32
    character(len=8), parameter, public :: KIND_NAMES(N_KINDS) = [character(len=8) :: &
        'SEG2', 'TRIA3', 'TRIA6', 'TRIA9', 'QUAD4', 'QUAD8', 'QUAD12', 'PENTAC6', 'PENTAC12', &
        'PENTAC18', 'HEXACE8', 'HEXACE16', 'HEXACE24', 'TETRA4', 'TETRA10', 'PENTA6', &
        'PENTA15', 'PENTA24', 'HEXA8', 'HEXA20', 'HEXA32', '', '', '', '', '', '', '', &
        'SEG2', 'POI1', 'SEG2', 'POI1', 'POI1', 'SEG2', 'SEG3']
    integer(i4), parameter, public :: KIND_NODES(N_KINDS) = [2, 3, 6, 9, 4, 8, 12, 6, 12, &
        18, 8, 16, 24, 4, 10, 6, 15, 24, 8, 20, 32, 0, 0, 0, 0, 0, 0, 0, 2, 1, 2, 1, 1, 2, 3]
    !> The kinds parasol's meshes hold (points, lines, triangles and quadrangles).
    logical, parameter, public :: KIND_PARASOL(N_KINDS) = [ &
        .true., .true., .true., .false., .true., .true., .false., .false., .false., &
        .false., .false., .false., .false., .false., .false., .false., .false., .false., &
        .false., .false., .false., .false., .false., .false., .false., .false., .false., &
        .false., .true., .true., .true., .true., .true., .true., .true.]
    !> Beams: one more line (orientation node, cross sections) before their nodes.
    integer(i4), parameter, public :: BEAM_DESCRIPTORS(5) = [11, 21, 22, 23, 24]

contains

    !> Code_Aster's order of the n nodes of a cell of `kind` read in the file's order: node k
    !> of the cell is the file's node order(k) (inistb lists quadratic cells' corners first).
    pure function kind_order(kind, n) result(order)
        integer(i4), intent(in) :: kind, n
        integer(i4) :: order(n)
        integer(i4) :: k
        select case (kind)
        case (3)          ! TRIA6: corner, mid, corner, mid, corner, mid
            order = [1, 3, 5, 2, 4, 6]
        case (6)          ! QUAD8
            order = [1, 3, 5, 7, 2, 4, 6, 8]
        case (35)         ! SEG3: end, mid, end
            order = [1, 3, 2]
        case default
            order = [(k, k = 1, n)]
        end select
    end function kind_order

    !> The kind of FE descriptor `descriptor` (cov4v5), 0 when Code_Aster converts none.
    pure integer(i4) function cell_kind(descriptor) result(kind)
        integer(i4), intent(in) :: descriptor
        select case (descriptor)
        case (11, 21, 23, 171)
            kind = 1
        case (41, 51, 61, 74, 81, 91)
            kind = 2
        case (42, 52, 62, 72, 82, 92)
            kind = 3
        case (43, 53, 63, 73, 93)
            kind = 4
        case (44, 54, 64, 71, 84, 94)
            kind = 5
        case (45, 55, 65, 75, 85, 95)
            kind = 6
        case (46, 56, 66, 76, 96)
            kind = 7
        case (101:106)
            kind = descriptor - 93
        case (111)
            kind = 14
        case (118)
            kind = 15
        case (112:117)
            kind = descriptor - 96
        case (136, 137)
            kind = 29
        case (138, 139)
            kind = 30
        case (141)
            kind = 31
        case (142)
            kind = 32
        case (161)
            kind = 33
        case (121)
            kind = 34
        case (22, 24, 172)
            kind = 35
        case default
            kind = 0
        end select
    end function cell_kind

end module mesh_ideas_tables
