!> The selections behind DEFI_GROUP (U4.22.01): ordered set operations on lists of nodes or
!> cells, the nodes of cells by role, and the geometric and topological choices of cells
!> (TYPE_MAILLE, APPUI, SPHERE, CYLINDRE, BANDE, FACE_NORMALE) and of nodes (ENV_SPHERE,
!> ENV_CYLINDRE, PLAN). Every selection is one pass over the nodes and the connectivity,
!> O(n); lists keep Code_Aster's order (op0104's utlisi for the set operations, increasing
!> numbers for the geometric ones).
module mesh_group_select
    use kinds, only: dp, i4
    use mesh_types, only: mesh_t
    use mesh_cell_kinds, only: cell_dimension, role_range, type_matches_filter, ROLE_VERTEX
    use mesh_geometry, only: axis_distance, edge_normal_2d, face_normal
    implicit none
    private

    !> How many of a cell's nodes must pass a node test for the cell to be chosen
    !> (CRIT_NOEUD of SPHERE, CYLINDRE, BANDE; TYPE_APPUI of APPUI).
    integer(i4), parameter, public :: AT_LEAST_ONE = 1, ALL_NODES = 2, MAJORITY = 3, &
        ALL_VERTICES = 4

    public :: ordered_union, ordered_intersection, ordered_difference, first_occurrences
    public :: filter_cells_by_type, nodes_of_cells_by_role, cells_by_node_mask
    public :: sphere_mask, axis_mask, band_mask, cells_facing, criterion_code
    public :: nodes_on_sphere, nodes_on_cylinder, nodes_on_plane, min_edge_length

contains

    ! ---- ordered set operations (op0104/utlisi): a's order, then b's ---------------------

    !> a, then the items of b not in a (in b's order). n: largest possible item.
    function ordered_union(a, b, n) result(c)
        integer(i4), intent(in) :: a(:), b(:), n
        integer(i4), allocatable :: c(:)
        logical, allocatable :: seen(:)
        integer(i4) :: i, k
        allocate (seen(n), source=.false.)
        allocate (c(size(a) + size(b)))
        c(1:size(a)) = a
        seen(a) = .true.
        k = size(a, kind=i4)
        do i = 1, size(b, kind=i4)
            if (seen(b(i))) cycle
            seen(b(i)) = .true.
            k = k + 1
            c(k) = b(i)
        end do
        c = c(1:k)
    end function ordered_union

    !> The items of a that are in b, in a's order.
    function ordered_intersection(a, b, n) result(c)
        integer(i4), intent(in) :: a(:), b(:), n
        integer(i4), allocatable :: c(:)
        logical, allocatable :: in_b(:)
        allocate (in_b(n), source=.false.)
        in_b(b) = .true.
        c = pack(a, in_b(a))
    end function ordered_intersection

    !> The items of a that are not in b, in a's order.
    function ordered_difference(a, b, n) result(c)
        integer(i4), intent(in) :: a(:), b(:), n
        integer(i4), allocatable :: c(:)
        logical, allocatable :: in_b(:)
        allocate (in_b(n), source=.false.)
        in_b(b) = .true.
        c = pack(a, .not. in_b(a))
    end function ordered_difference

    !> The first occurrence of each item of a, in a's order; `repeated` gets the positions
    !> in a of the items dropped (for the alarms of MAILLE/NOEUD given twice).
    subroutine first_occurrences(a, n, c, repeated)
        integer(i4), intent(in) :: a(:), n
        integer(i4), allocatable, intent(out) :: c(:), repeated(:)
        logical, allocatable :: seen(:), keep(:)
        integer(i4) :: i
        allocate (seen(n), source=.false.)
        allocate (keep(size(a)))
        do i = 1, size(a, kind=i4)
            keep(i) = .not. seen(a(i))
            seen(a(i)) = .true.
        end do
        c = pack(a, keep)
        repeated = pack([(i, i = 1, size(a, kind=i4))], .not. keep)
    end subroutine first_occurrences

    ! ---- cells and their nodes --------------------------------------------------------------

    !> The cells of `cells` whose type passes TYPE_MAILLE `filter` (TOUT, 1D, 2D, 3D or a
    !> type name), in their order.
    function filter_cells_by_type(mesh, cells, filter) result(kept)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:)
        character(len=*), intent(in) :: filter
        integer(i4), allocatable :: kept(:)
        logical, allocatable :: ok(:)
        integer(i4) :: i
        allocate (ok(size(cells)))
        do i = 1, size(cells, kind=i4)
            ok(i) = type_matches_filter(mesh%cell_type(cells(i)), filter)
        end do
        kept = pack(cells, ok)
    end function filter_cells_by_type

    !> The distinct nodes of `role` (ROLE_ALL, ROLE_VERTEX, ROLE_MID_EDGE, ROLE_CENTRE) of the
    !> cells, in increasing node number (Code_Aster's gmgnre).
    function nodes_of_cells_by_role(mesh, cells, role) result(nodes)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:), role
        integer(i4), allocatable :: nodes(:)
        logical, allocatable :: used(:)
        integer(i4) :: i, c, first, last, p0, n
        allocate (used(mesh%n_nodes), source=.false.)
        do i = 1, size(cells, kind=i4)
            c = cells(i)
            call role_range(mesh%cell_type(c), role, first, last)
            p0 = mesh%cell_ptr(c) - 1
            if (last >= first) used(mesh%cell_nodes(p0 + first:p0 + last)) = .true.
        end do
        nodes = pack([(n, n = 1, mesh%n_nodes)], used)
    end function nodes_of_cells_by_role

    !> The cells (in increasing number) whose nodes pass `mask` according to `criterion`:
    !> AT_LEAST_ONE node, ALL_NODES, a MAJORITY (at least (n+1)/2 of its n nodes), or
    !> ALL_VERTICES (TYPE_APPUI='SOMMET'). Only the cells flagged in `candidates`, when given,
    !> are considered.
    function cells_by_node_mask(mesh, mask, criterion, candidates) result(cells)
        type(mesh_t), intent(in) :: mesh
        logical, intent(in) :: mask(:)
        integer(i4), intent(in) :: criterion
        logical, intent(in), optional :: candidates(:)
        integer(i4), allocatable :: cells(:)
        logical, allocatable :: chosen(:)
        integer(i4) :: c, p0, nn, hits, first, last
        allocate (chosen(mesh%n_cells), source=.false.)
        do c = 1, mesh%n_cells
            if (present(candidates)) then
                if (.not. candidates(c)) cycle
            end if
            p0 = mesh%cell_ptr(c) - 1
            first = 1
            last = mesh%cell_ptr(c + 1) - mesh%cell_ptr(c)
            if (criterion == ALL_VERTICES) call role_range(mesh%cell_type(c), ROLE_VERTEX, &
                                                           first, last)
            nn = last - first + 1
            hits = count(mask(mesh%cell_nodes(p0 + first:p0 + last)), kind=i4)
            select case (criterion)
            case (AT_LEAST_ONE)
                chosen(c) = hits >= 1
            case (ALL_NODES, ALL_VERTICES)
                chosen(c) = hits == nn .and. nn > 0
            case (MAJORITY)
                chosen(c) = hits >= (nn + 1) / 2 .and. nn > 0
            end select
        end do
        cells = pack([(c, c = 1, mesh%n_cells)], chosen)
    end function cells_by_node_mask

    !> The criterion code of CRIT_NOEUD / TYPE_APPUI text (0 for an unknown word).
    pure integer(i4) function criterion_code(word) result(code)
        character(len=*), intent(in) :: word
        select case (word)
        case ('AU_MOINS_UN')
            code = AT_LEAST_ONE
        case ('TOUS', 'TOUT')
            code = ALL_NODES
        case ('MAJORITE')
            code = MAJORITY
        case ('SOMMET')
            code = ALL_VERTICES
        case default
            code = 0
        end select
    end function criterion_code

    ! ---- node masks of the geometric cell options ------------------------------------------

    !> Nodes within `radius` of `centre` (|x - x0|^2 <= r^2: cgmasp); ndim = 2 ignores z.
    function sphere_mask(mesh, centre, radius, ndim) result(mask)
        type(mesh_t), intent(in) :: mesh
        real(dp), intent(in) :: centre(3), radius
        integer(i4), intent(in) :: ndim
        logical, allocatable :: mask(:)
        integer(i4) :: k
        allocate (mask(mesh%n_nodes))
        do k = 1, mesh%n_nodes
            mask(k) = sum((mesh%coords(1:ndim, k) - centre(1:ndim))**2) <= radius**2
        end do
    end function sphere_mask

    !> Nodes within `radius` of the axis through `centre` along the unit vector `axis`
    !> (cgmacy, 3D).
    function axis_mask(mesh, centre, axis, radius) result(mask)
        type(mesh_t), intent(in) :: mesh
        real(dp), intent(in) :: centre(3), axis(3), radius
        logical, allocatable :: mask(:)
        integer(i4) :: k
        allocate (mask(mesh%n_nodes))
        do k = 1, mesh%n_nodes
            mask(k) = axis_distance(mesh%coords(:, k), centre, axis) <= radius
        end do
    end function axis_mask

    !> Nodes at most `dist` from the plane (line in 2D) through `centre` normal to the unit
    !> vector `normal`: |(x - x0).n| <= dist (cgmaba). ndim = 2 ignores z.
    function band_mask(mesh, centre, normal, dist, ndim) result(mask)
        type(mesh_t), intent(in) :: mesh
        real(dp), intent(in) :: centre(3), normal(3), dist
        integer(i4), intent(in) :: ndim
        logical, allocatable :: mask(:)
        integer(i4) :: k
        allocate (mask(mesh%n_nodes))
        do k = 1, mesh%n_nodes
            mask(k) = abs(dot_product(mesh%coords(1:ndim, k) - centre(1:ndim), &
                                      normal(1:ndim))) <= dist
        end do
    end function band_mask

    !> FACE_NORMALE (cgmafn): the cells whose normal makes an angle below `tolerance`
    !> (radians) with the unit vector `normal`: edges (SEG) of a mesh whose coordinates are
    !> 2D (`plane`), faces (TRIA, QUAD) otherwise; with `same_sense` (VERI_SIGNE='OUI') the
    !> normal must also point the same way. In increasing cell number.
    function cells_facing(mesh, normal, tolerance, same_sense, plane) result(cells)
        type(mesh_t), intent(in) :: mesh
        real(dp), intent(in) :: normal(3), tolerance
        logical, intent(in) :: same_sense, plane
        integer(i4), allocatable :: cells(:)
        logical, allocatable :: chosen(:)
        real(dp) :: n(3), cosine
        integer(i4) :: c, p0, d
        logical :: ok
        allocate (chosen(mesh%n_cells), source=.false.)
        do c = 1, mesh%n_cells
            d = cell_dimension(mesh%cell_type(c))
            p0 = mesh%cell_ptr(c) - 1
            ok = .false.
            if (plane .and. d == 1) then
                call edge_normal_2d(mesh%coords(:, mesh%cell_nodes(p0 + 1)), &
                                    mesh%coords(:, mesh%cell_nodes(p0 + 2)), n, ok)
            else if (.not. plane .and. d == 2) then
                call face_normal(mesh%coords(:, mesh%cell_nodes(p0 + 1)), &
                                 mesh%coords(:, mesh%cell_nodes(p0 + 2)), &
                                 mesh%coords(:, mesh%cell_nodes(p0 + 3)), n, ok)
            end if
            if (.not. ok) cycle
            cosine = dot_product(n, normal)
            if (same_sense .and. cosine <= 0.0_dp) cycle
            chosen(c) = acos(min(1.0_dp, abs(cosine))) < abs(tolerance)
        end do
        cells = pack([(c, c = 1, mesh%n_cells)], chosen)
    end function cells_facing

    ! ---- node selections of CREA_GROUP_NO -------------------------------------------------

    !> ENV_SPHERE (cgnoes): nodes whose distance to `centre` is within `precision` of
    !> `radius`, in increasing number; ndim = 2 ignores z.
    function nodes_on_sphere(mesh, centre, radius, precision, ndim) result(nodes)
        type(mesh_t), intent(in) :: mesh
        real(dp), intent(in) :: centre(3), radius, precision
        integer(i4), intent(in) :: ndim
        integer(i4), allocatable :: nodes(:)
        logical, allocatable :: on(:)
        integer(i4) :: k
        allocate (on(mesh%n_nodes))
        do k = 1, mesh%n_nodes
            on(k) = abs(norm2(mesh%coords(1:ndim, k) - centre(1:ndim)) - radius) <= precision
        end do
        nodes = pack([(k, k = 1, mesh%n_nodes)], on)
    end function nodes_on_sphere

    !> ENV_CYLINDRE (cgnoec): nodes whose distance to the axis is within `precision` of
    !> `radius`.
    function nodes_on_cylinder(mesh, centre, axis, radius, precision) result(nodes)
        type(mesh_t), intent(in) :: mesh
        real(dp), intent(in) :: centre(3), axis(3), radius, precision
        integer(i4), allocatable :: nodes(:)
        logical, allocatable :: on(:)
        integer(i4) :: k
        allocate (on(mesh%n_nodes))
        do k = 1, mesh%n_nodes
            on(k) = abs(axis_distance(mesh%coords(:, k), centre, axis) - radius) <= precision
        end do
        nodes = pack([(k, k = 1, mesh%n_nodes)], on)
    end function nodes_on_cylinder

    !> PLAN (cgnop0): nodes at most `precision` from the plane (line in 2D) through `centre`
    !> normal to the unit vector `normal`.
    function nodes_on_plane(mesh, centre, normal, precision, ndim) result(nodes)
        type(mesh_t), intent(in) :: mesh
        real(dp), intent(in) :: centre(3), normal(3), precision
        integer(i4), intent(in) :: ndim
        integer(i4), allocatable :: nodes(:)
        logical, allocatable :: mask(:)
        integer(i4) :: k
        mask = band_mask(mesh, centre, normal, precision, ndim)
        nodes = pack([(k, k = 1, mesh%n_nodes)], mask)
    end function nodes_on_plane

    !> The shortest edge of the mesh's cells (Code_Aster's AR_MIN of CARA_GEOM): over the
    !> edges between consecutive vertices of SEG, TRIA and QUAD cells; 0 for a mesh of POI1
    !> only.
    real(dp) function min_edge_length(mesh) result(shortest)
        type(mesh_t), intent(in) :: mesh
        integer(i4) :: c, p0, nv, i, a, b, first, last
        shortest = huge(1.0_dp)
        do c = 1, mesh%n_cells
            if (cell_dimension(mesh%cell_type(c)) < 1) cycle
            call role_range(mesh%cell_type(c), ROLE_VERTEX, first, last)
            nv = last
            p0 = mesh%cell_ptr(c) - 1
            do i = 1, nv
                if (nv == 2 .and. i == 2) exit
                a = mesh%cell_nodes(p0 + i)
                b = mesh%cell_nodes(p0 + mod(i, nv) + 1)
                shortest = min(shortest, norm2(mesh%coords(:, a) - mesh%coords(:, b)))
            end do
        end do
        if (shortest > 0.5_dp * huge(1.0_dp)) shortest = 0.0_dp
    end function min_edge_length

end module mesh_group_select
