!> Ordered node groups along a line (DEFI_GROUP/CREA_GROUP_NO, U4.22.01): NOEUD_ORDO walks
!> the SEG cells of a line from its origin to its end; SEGM_DROI_ORDO sorts nodes lying on
!> a segment by their abscissa. Their order is what ABSC_CURV in tables and the node order
!> of later commands see, so it follows Code_Aster's (cgnoor/ornofd, cgnoso/oreino):
!>  - NOEUD_ORDO: origin GROUP_NO_ORIG, else the first line end met when reading the cells'
!>    first nodes, then their second nodes (a closed line needs GROUP_NO_ORIG or
!>    ORIGINE='SANS', which starts at the first cell's first node); from each node the walk
!>    takes, of the cells not yet walked, the first in the given order (which decides the
!>    sense around a closed line); a closed line ends on its origin again (listed twice);
!>    SEG3 mid-nodes come between their ends; of the two senses round a closed line,
!>    VECT_ORIE chooses the one whose first step runs closer to it.
!>  - SEGM_DROI_ORDO: every node within PRECISION of the line AB (ABSOLU: a length;
!>    RELATIF: a fraction of |AB|), none beyond the segment, no two at the same abscissa;
!>    stable sort by abscissa.
!> Both are O(n) / O(n log n), where Code_Aster's are quadratic.
module mesh_node_path
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MESH_ERROR
    use strings, only: to_text
    use mesh_types, only: mesh_t, node_name, cell_name, CELL_TYPE_NAMES
    use mesh_cell_kinds, only: cell_dimension
    use stable_sort, only: real_order
    implicit none
    private

    public :: order_line_nodes, order_segment_nodes

contains

    !> NOEUD_ORDO: the nodes of the line formed by `cells` (SEG cells, all of one type), in
    !> order from the origin.
    !>  origin, extremity : in, node numbers of GROUP_NO_ORIG / GROUP_NO_EXTR (0: not given)
    !>  any_origin        : in, ORIGINE='SANS' (a closed line starts at its first cell)
    !>  orientation       : in, VECT_ORIE (zero: not given)
    !>  nodes             : out, the ordered nodes
    !>  chosen_origin     : out, the origin used (for the .mess)
    !>  st                : out, a located-free message (the caller locates it): no cell,
    !>                      a cell that is not a SEG or of another type than the first, cells
    !>                      that do not form one line, an origin or extremity that is not an
    !>                      end of the line, a closed line without origin, an extremity the
    !>                      walk does not end on
    subroutine order_line_nodes(mesh, cells, origin, extremity, any_origin, orientation, &
                                nodes, chosen_origin, st)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:), origin, extremity
        logical, intent(in) :: any_origin
        real(dp), intent(in) :: orientation(3)
        integer(i4), allocatable, intent(out) :: nodes(:)
        integer(i4), intent(out) :: chosen_origin
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: ends(:, :), degree(:), ptr(:), incident(:), fill(:)
        logical, allocatable :: walked(:)
        integer(i4) :: m, i, k, node, next, pos, step, per_cell
        real(dp) :: first_step, last_step, a(3), b(3)
        chosen_origin = 0
        m = size(cells, kind=i4)
        if (m == 0) then
            call set_error(st, STATUS_MESH_ERROR, 'the GROUP_MA hold no cell')
            return
        end if
        do i = 1, m
            if (cell_dimension(mesh%cell_type(cells(i))) /= 1) then
                call set_error(st, STATUS_MESH_ERROR, 'cell ' // cell_name(mesh, cells(i)) // &
                    ' is a ' // trim(CELL_TYPE_NAMES(mesh%cell_type(cells(i)))) // &
                    ': a line is made of SEG cells')
                return
            end if
            if (mesh%cell_type(cells(i)) /= mesh%cell_type(cells(1))) then
                call set_error(st, STATUS_MESH_ERROR, 'cell ' // cell_name(mesh, cells(i)) // &
                    ' is a ' // trim(CELL_TYPE_NAMES(mesh%cell_type(cells(i)))) // &
                    ' and cell ' // cell_name(mesh, cells(1)) // ' a ' // &
                    trim(CELL_TYPE_NAMES(mesh%cell_type(cells(1)))) // &
                    ': the cells of a line must all be of one type')
                return
            end if
        end do
        ! the two end nodes of each cell, and how many cell ends meet at each node
        allocate (ends(2, m), degree(mesh%n_nodes), source=0_i4)
        do i = 1, m
            ends(:, i) = mesh%cell_nodes(mesh%cell_ptr(cells(i)):mesh%cell_ptr(cells(i)) + 1)
            degree(ends(1, i)) = degree(ends(1, i)) + 1
            degree(ends(2, i)) = degree(ends(2, i)) + 1
        end do
        if (count(degree == 1) > 2 .or. any(degree > 2)) then
            k = findloc(degree > 2, .true., dim=1)
            if (k > 0) then
                call set_error(st, STATUS_MESH_ERROR, 'the cells do not form one line: ' // &
                    to_text(degree(k)) // ' of them meet at node ' // node_name(mesh, k))
            else
                call set_error(st, STATUS_MESH_ERROR, 'the cells do not form one line: ' // &
                    'it has ' // to_text(count(degree == 1, kind=i4)) // ' ends')
            end if
            return
        end if
        call check_end(extremity, 'GROUP_NO_EXTR')
        if (st%failed()) return
        call check_end(origin, 'GROUP_NO_ORIG')
        if (st%failed()) return
        chosen_origin = origin
        if (chosen_origin == 0) then
            ! the first line end met reading the cells' first nodes, then their second nodes
            do k = 1, 2
                do i = 1, m
                    if (degree(ends(k, i)) == 1) then
                        chosen_origin = ends(k, i)
                        exit
                    end if
                end do
                if (chosen_origin > 0) exit
            end do
            if (chosen_origin == 0) then
                if (.not. any_origin) then
                    call set_error(st, STATUS_MESH_ERROR, 'the line is closed: say where it ' // &
                        'starts with GROUP_NO_ORIG (or ORIGINE=''SANS'' to start at its ' // &
                        'first cell)')
                    return
                end if
                chosen_origin = ends(1, 1)
            end if
        end if
        ! cells incident to each node (positions in `cells`, increasing)
        allocate (ptr(mesh%n_nodes + 1))
        ptr(1) = 1
        do k = 1, mesh%n_nodes
            ptr(k + 1) = ptr(k) + degree(k)
        end do
        allocate (incident(2 * m), fill(mesh%n_nodes), source=0_i4)
        do i = 1, m
            do k = 1, 2
                node = ends(k, i)
                incident(ptr(node) + fill(node)) = i
                fill(node) = fill(node) + 1
            end do
        end do
        per_cell = 1                                        ! SEG2: the start node
        if (cell_node_count(cells(1)) >= 3) per_cell = 2    ! SEG3: start and middle
        allocate (nodes(per_cell * m + 1), source=0_i4)
        allocate (walked(m), source=.false.)
        node = chosen_origin
        pos = 0
        do step = 1, m
            next = 0
            do k = ptr(node), ptr(node + 1) - 1
                if (walked(incident(k))) cycle
                if (next == 0) next = incident(k)
                next = min(next, incident(k))
            end do
            if (next == 0) then
                call set_error(st, STATUS_MESH_ERROR, 'the cells do not form one connected ' // &
                    'line: the walk from node ' // node_name(mesh, chosen_origin) // &
                    ' stops at node ' // node_name(mesh, node) // ' after ' // &
                    to_text(step - 1) // ' of ' // to_text(m) // ' cells')
                return
            end if
            walked(next) = .true.
            pos = pos + 1
            nodes(pos) = node
            if (per_cell == 2) then
                pos = pos + 1
                nodes(pos) = mesh%cell_nodes(mesh%cell_ptr(cells(next)) + 2)
            end if
            node = merge(ends(2, next), ends(1, next), ends(1, next) == node)
        end do
        nodes(pos + 1) = node
        if (extremity > 0 .and. node /= extremity) then
            call set_error(st, STATUS_MESH_ERROR, 'the line from node ' // &
                node_name(mesh, chosen_origin) // ' ends at node ' // node_name(mesh, node) // &
                ', not at the GROUP_NO_EXTR node ' // node_name(mesh, extremity))
            return
        end if
        ! VECT_ORIE: the sense round a closed line
        if (any(abs(orientation) > 0.0_dp) .and. size(nodes) >= 3 .and. &
            nodes(1) == nodes(size(nodes))) then
            a = mesh%coords(:, nodes(2)) - mesh%coords(:, nodes(1))
            b = mesh%coords(:, nodes(size(nodes) - 1)) - mesh%coords(:, nodes(size(nodes)))
            first_step = dot_product(a, orientation) / norm2(a)
            last_step = dot_product(b, orientation) / norm2(b)
            if (last_step > first_step) nodes = nodes(size(nodes):1:-1)
        end if
    contains
        ! An origin or extremity must be an end of the line: met once among the cell ends
        ! (twice is allowed when origin and extremity are the same node: a closed line).
        subroutine check_end(n, key)
            integer(i4), intent(in) :: n
            character(len=*), intent(in) :: key
            if (n == 0) return
            if (degree(n) == 0) then
                call set_error(st, STATUS_MESH_ERROR, key // ': node ' // node_name(mesh, n) // &
                    ' is not on the line')
            else if (degree(n) /= 1 .and. .not. (origin == extremity)) then
                call set_error(st, STATUS_MESH_ERROR, key // ': node ' // node_name(mesh, n) // &
                    ' is not an end of the line (' // to_text(degree(n)) // ' cells meet there)')
            end if
        end subroutine check_end

        integer(i4) function cell_node_count(c)
            integer(i4), intent(in) :: c
            cell_node_count = mesh%cell_ptr(c + 1) - mesh%cell_ptr(c)
        end function cell_node_count
    end subroutine order_line_nodes

    !> SEGM_DROI_ORDO: `nodes` sorted by their abscissa along the segment from node `origin`
    !> to node `extremity` (stable).
    !>  precision : in, PRECISION;  relative : in, CRITERE='RELATIF'
    !>  st : out, a zero-length segment, a node off the line or beyond the segment (with its
    !>       distance), two nodes at one abscissa
    subroutine order_segment_nodes(mesh, nodes, origin, extremity, precision, relative, st)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(inout) :: nodes(:)
        integer(i4), intent(in) :: origin, extremity
        real(dp), intent(in) :: precision
        logical, intent(in) :: relative
        type(status_t), intent(out) :: st
        real(dp), allocatable :: abscissa(:)
        integer(i4), allocatable :: order(:)
        real(dp) :: a(3), ab(3), am(3), ab2, am2, c, off
        integer(i4) :: i
        a = mesh%coords(:, origin)
        ab = mesh%coords(:, extremity) - a
        ab2 = dot_product(ab, ab)
        if (.not. (ab2 > 0.0_dp)) then
            call set_error(st, STATUS_MESH_ERROR, 'the segment from node ' // &
                node_name(mesh, origin) // ' to node ' // node_name(mesh, extremity) // &
                ' has zero length')
            return
        end if
        allocate (abscissa(size(nodes)))
        do i = 1, size(nodes, kind=i4)
            am = mesh%coords(:, nodes(i)) - a
            c = dot_product(am, ab) / ab2
            am2 = dot_product(am, am)
            off = norm2(am - c * ab)
            if (relative) off = off / sqrt(ab2)
            if (off > precision) then
                call set_error(st, STATUS_MESH_ERROR, 'node ' // node_name(mesh, nodes(i)) // &
                    ' is ' // to_text(norm2(am - c * ab)) // ' away from the line ' // &
                    node_name(mesh, origin) // '-' // node_name(mesh, extremity) // &
                    ' (more than PRECISION)')
                return
            end if
            ! beyond the segment's length from A (oreino's test)
            if ((c < 0.0_dp .or. am2 > ab2) .and. (am2 - ab2) / ab2 > epsilon(1.0_dp)) then
                call set_error(st, STATUS_MESH_ERROR, 'node ' // node_name(mesh, nodes(i)) // &
                    ' lies beyond the segment ' // node_name(mesh, origin) // '-' // &
                    node_name(mesh, extremity) // ' (abscissa ' // to_text(c) // ' of its length)')
                return
            end if
            abscissa(i) = c
        end do
        order = real_order(abscissa)
        nodes = nodes(order)
        abscissa = abscissa(order)
        do i = 1, size(nodes, kind=i4) - 1
            if (.not. (abscissa(i) < abscissa(i + 1))) then
                call set_error(st, STATUS_MESH_ERROR, 'nodes ' // node_name(mesh, nodes(i)) // &
                    ' and ' // node_name(mesh, nodes(i + 1)) // ' are at the same abscissa ' // &
                    'on the segment')
                return
            end if
        end do
    end subroutine order_segment_nodes

end module mesh_node_path
