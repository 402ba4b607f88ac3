!> DEFI_GROUP/CREA_GROUP_NO OPTION='INCLUSION' (U4.22.01): which of a list of nodes lie in
!> the cells of another group (of the same mesh or another), within a distance, as
!> Code_Aster's projection (pj2dco, pj4dco) decides it: CAS_FIGURE='2D' on the plane cells
!> (TRIA, QUAD: their vertices as a polygon in the (x, y) plane), '2.5D' on surface cells in
!> space (split into triangles). The cells are binned once on a uniform grid of about one
!> bin per cell, so each node is tested against the few cells of its bin: O(nodes + cells).
module mesh_inclusion
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MESH_ERROR
    use mesh_types, only: mesh_t
    use mesh_cell_kinds, only: cell_dimension, role_range, ROLE_VERTEX
    use mesh_geometry, only: point_in_polygon_2d, point_in_triangle_3d
    implicit none
    private

    integer(i4), parameter, public :: INCLUSION_2D = 1, INCLUSION_SURFACE = 2
    !> Most bins per axis (bounds the grid's memory whatever the cells' sizes).
    integer(i4), parameter :: MAX_BINS_PER_AXIS = 2048

    public :: nodes_in_cells

contains

    !> The nodes of `candidates` (numbers in `mesh`) lying in one of the cells `cells` of
    !> `other` within `distance`, in the candidates' order.
    !>  mode : INCLUSION_2D or INCLUSION_SURFACE
    !>  st   : out, no plane / surface cell among `cells`
    subroutine nodes_in_cells(mesh, candidates, other, cells, distance, mode, nodes, st)
        type(mesh_t), intent(in) :: mesh, other
        integer(i4), intent(in) :: candidates(:), cells(:), mode
        real(dp), intent(in) :: distance
        integer(i4), allocatable, intent(out) :: nodes(:)
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: faces(:), ptr(:), members(:), fill(:)
        real(dp) :: lo(3), hi(3), h(3), box_lo(3), box_hi(3)
        integer(i4) :: nbins(3), ndim, i, f, k, b(3), b_lo(3), b_hi(3), ix, iy, iz
        integer(i8) :: bin
        logical, allocatable :: inside(:)
        faces = pack(cells, [(cell_dimension(other%cell_type(cells(i))) == 2, &
                              i = 1, size(cells))])
        if (size(faces) == 0) then
            call set_error(st, STATUS_MESH_ERROR, 'the GROUP_MA_INCL hold no ' // &
                trim(merge('plane cell (TRIA, QUAD)  ', 'surface cell (TRIA, QUAD)', &
                mode == INCLUSION_2D)) // ' to find the nodes in')
            return
        end if
        ndim = merge(2, 3, mode == INCLUSION_2D)
        ! the grid: the cells' bounding box, widened by the distance
        lo = huge(1.0_dp)
        hi = -huge(1.0_dp)
        do i = 1, size(faces, kind=i4)
            call face_box(faces(i), box_lo, box_hi)
            lo = min(lo, box_lo)
            hi = max(hi, box_hi)
        end do
        nbins = 1
        nbins(1:ndim) = max(1, min(MAX_BINS_PER_AXIS, &
            ceiling(real(size(faces), dp)**(1.0_dp / ndim), i4)))
        h = 1.0_dp
        do k = 1, ndim
            if (hi(k) > lo(k)) then
                h(k) = (hi(k) - lo(k)) / nbins(k)
            else
                nbins(k) = 1
            end if
        end do
        ! bins -> cells, in compressed rows (two passes: counts, then members)
        allocate (ptr(product(int(nbins, i8)) + 1), source=0_i4)
        do f = 1, size(faces, kind=i4)
            call face_bins(faces(f), b_lo, b_hi)
            do iz = b_lo(3), b_hi(3)
                do iy = b_lo(2), b_hi(2)
                    do ix = b_lo(1), b_hi(1)
                        bin = bin_index([ix, iy, iz])
                        ptr(bin + 1) = ptr(bin + 1) + 1
                    end do
                end do
            end do
        end do
        ptr(1) = 1
        do k = 1, size(ptr) - 1
            ptr(k + 1) = ptr(k + 1) + ptr(k)
        end do
        allocate (members(ptr(size(ptr)) - 1), fill(size(ptr) - 1), source=0_i4)
        do f = 1, size(faces, kind=i4)
            call face_bins(faces(f), b_lo, b_hi)
            do iz = b_lo(3), b_hi(3)
                do iy = b_lo(2), b_hi(2)
                    do ix = b_lo(1), b_hi(1)
                        bin = bin_index([ix, iy, iz])
                        members(ptr(bin) + fill(bin)) = faces(f)
                        fill(bin) = fill(bin) + 1
                    end do
                end do
            end do
        end do
        ! each candidate against the cells of its bin
        allocate (inside(size(candidates)), source=.false.)
        do i = 1, size(candidates, kind=i4)
            associate (p => mesh%coords(:, candidates(i)))
                if (any(p(1:ndim) < lo(1:ndim) .or. p(1:ndim) > hi(1:ndim))) cycle
                do k = 1, 3
                    b(k) = min(nbins(k), max(1, 1 + int((p(k) - lo(k)) / h(k), i4)))
                end do
                if (ndim == 2) b(3) = 1
                bin = bin_index(b)
                do k = ptr(bin), ptr(bin + 1) - 1
                    if (contains(members(k), p)) then
                        inside(i) = .true.
                        exit
                    end if
                end do
            end associate
        end do
        nodes = pack(candidates, inside)
    contains
        ! The bounding box of a cell's vertices, widened by the distance (z flat in 2D).
        subroutine face_box(c, box_lo, box_hi)
            integer(i4), intent(in) :: c
            real(dp), intent(out) :: box_lo(3), box_hi(3)
            integer(i4) :: first, last, p0
            call role_range(other%cell_type(c), ROLE_VERTEX, first, last)
            p0 = other%cell_ptr(c) - 1
            box_lo = minval(other%coords(:, other%cell_nodes(p0 + first:p0 + last)), dim=2) &
                     - distance
            box_hi = maxval(other%coords(:, other%cell_nodes(p0 + first:p0 + last)), dim=2) &
                     + distance
            if (ndim == 2) then
                box_lo(3) = 0.0_dp
                box_hi(3) = 0.0_dp
            end if
        end subroutine face_box

        ! The range of bins a cell's widened box covers.
        subroutine face_bins(c, b_lo, b_hi)
            integer(i4), intent(in) :: c
            integer(i4), intent(out) :: b_lo(3), b_hi(3)
            real(dp) :: box_lo(3), box_hi(3)
            integer(i4) :: k
            call face_box(c, box_lo, box_hi)
            b_lo = 1
            b_hi = 1
            do k = 1, ndim
                if (nbins(k) == 1) cycle
                b_lo(k) = min(nbins(k), max(1, 1 + int((box_lo(k) - lo(k)) / h(k), i4)))
                b_hi(k) = min(nbins(k), max(1, 1 + int((box_hi(k) - lo(k)) / h(k), i4)))
            end do
        end subroutine face_bins

        integer(i8) function bin_index(b)
            integer(i4), intent(in) :: b(3)
            bin_index = b(1) + int(nbins(1), i8) * ((b(2) - 1) + int(nbins(2), i8) * (b(3) - 1))
        end function bin_index

        ! Point p in cell c of `other`, within the distance.
        logical function contains(c, p)
            integer(i4), intent(in) :: c
            real(dp), intent(in) :: p(3)
            integer(i4) :: first, last, p0, j
            real(dp), allocatable :: x(:, :)
            call role_range(other%cell_type(c), ROLE_VERTEX, first, last)
            p0 = other%cell_ptr(c) - 1
            x = other%coords(:, other%cell_nodes(p0 + first:p0 + last))
            if (mode == INCLUSION_2D) then
                contains = point_in_polygon_2d(p, x, distance)
                return
            end if
            contains = .false.
            do j = 2, last - 1     ! a fan of triangles from the first vertex
                contains = point_in_triangle_3d(p, x(:, 1), x(:, j), x(:, j + 1), distance)
                if (contains) return
            end do
        end function contains
    end subroutine nodes_in_cells

end module mesh_inclusion
