!> MACR_LIGN_COUPE's cut lines (U4.81.13, LIGN_COUPE): the points of each line (TYPE
!> SEGMENT or GROUP_NO), its title, components, DISTANCE_MAX, frame (REPERE with its
!> keywords) and quantity (INVARIANT, ELEM_PRINCIPAUX, TRAC_NOR, TRAC_DIR), read and checked
!> as Code_Aster's catalog and macro check them; macr_lign_coupe_command reads the field
!> along them.
module lign_coupe_lines
    use kinds, only: dp, i4
    use strings, only: string_t, to_text
    use status, only: status_t, STATUS_NOT_IMPLEMENTED
    use deck_command, only: keyword_set_t
    use mesh_types, only: mesh_t, find_node_group, nodes_of_group
    use table_keywords, only: relocate_at
    use lign_coupe_frames, only: segment_local_angles, LOCAL_EPSILON
    implicit none
    private

    public :: line_t, read_line

    !> What a line reads (as POST_RELEVE_T's rvcpnc QUANT on the line's mesh).
    integer, parameter, public :: Q_COMPONENTS = 1, Q_INVARIANTS = 2, Q_PRINCIPAL = 3, &
        Q_TRAC_NOR = 4, Q_TRAC_DIR = 5
    !> DETER cubes the tensor's components: they stay below this (POST_RELEVE_T's bound).
    real(dp), parameter, public :: CUBE_LIMIT = 1.0e100_dp
    character(len=*), parameter, public :: INVARIANT_NAMES = 'VMIS TRESCA TRACE DETER'
    character(len=*), parameter, public :: PRINCIPAL_NAMES = 'PRIN_1 PRIN_2 PRIN_3 VECT_1_X ' // &
        'VECT_1_Y VECT_1_Z VECT_2_X VECT_2_Y VECT_2_Z VECT_3_X VECT_3_Y VECT_3_Z'

    !> One cut line: its points and title.
    type :: line_t
        character(len=:), allocatable :: label
        real(dp), allocatable :: x(:, :)            !< (3, n) the points asked for
        type(string_t), allocatable :: asked(:)     !< NOM_CMP, none: every component
        real(dp) :: distance_max = 0.0_dp
        character(len=:), allocatable :: kind           !< TYPE: SEGMENT or GROUP_NO
        character(len=:), allocatable :: frame          !< REPERE
        real(dp) :: angles(3) = 0.0_dp                  !< UTILISATEUR, LOCAL on a SEGMENT
        real(dp) :: vect_y(3) = 0.0_dp                  !< LOCAL on a GROUP_NO (3D)
        real(dp) :: origin(3) = 0.0_dp, axis(3) = 0.0_dp   !< CYLINDRIQUE
        integer :: quantity = Q_COMPONENTS
        real(dp) :: direction(3) = 0.0_dp                !< TRAC_DIR
    end type line_t


    !> The fields whose components MACR_LIGN_COUPE turns (crea_resu_local); the others are
    !> read in the global frame with an alarm, as Code_Aster reads them.
    character(len=*), parameter, public :: TURNED_FIELDS = ' DEPL SIEF_ELNO SIGM_NOEU SIGM_ELNO ' // &
        'FLUX_ELNO FLUX_NOEU '

contains

    ! ---- the lines ---------------------------------------------------------------------

    !> Reads one LIGN_COUPE occurrence: its points, title, components and distance.
    subroutine read_line(occ, mesh, n_unnamed, line, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        integer, intent(inout) :: n_unnamed
        type(line_t), intent(out) :: line
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: kind, text, group
        real(dp) :: a(3), b(3)
        integer :: n, i
        integer(i4) :: g
        integer(i4), allocatable :: nodes(:)
        call occ%get_text('TYPE', kind, st)
        if (st%failed()) return
        call refuse_unbuilt(occ, kind, st)
        if (st%failed()) return
        if (occ%has('DISTANCE_MAX')) call occ%get_real('DISTANCE_MAX', line%distance_max, st)
        if (st%ok() .and. .not. line%distance_max >= 0.0_dp) call occ%error_at( &
            'DISTANCE_MAX', 'DISTANCE_MAX is a distance: >= 0', st)
        if (st%ok() .and. occ%has('NOM_CMP')) call occ%get_texts('NOM_CMP', line%asked, st)
        if (st%failed()) return
        if (.not. allocated(line%asked)) allocate (line%asked(0))
        line%kind = kind
        select case (kind)
        case ('SEGMENT')
            call check_block(occ, 'SEGMENT', 'GROUP_NO', st)
            if (st%ok() .and. .not. occ%has('NB_POINTS')) call occ%error_at('TYPE', &
                'TYPE=''SEGMENT'' needs NB_POINTS, the number of points of the line', st)
            if (st%ok()) call occ%get_int('NB_POINTS', n, st)
            if (st%ok()) call end_point(occ, mesh, 'COOR_ORIG', 'GROUP_NO_ORIG', a, st)
            if (st%ok()) call end_point(occ, mesh, 'COOR_EXTR', 'GROUP_NO_EXTR', b, st)
            if (st%failed()) return
            if (.not. norm2(b - a) > 0.0_dp) then
                call occ%error_at('NB_POINTS', 'the segment''s origin and end are the ' // &
                    'same point: the line has no direction', st)
                return
            end if
            allocate (line%x(3, n))
            do i = 1, n
                line%x(:, i) = a + (b - a) * (real(i - 1, dp) / real(n - 1, dp))
            end do
            n_unnamed = n_unnamed + 1
            line%label = 'l.coupe' // to_text(n_unnamed)
        case ('GROUP_NO')
            call check_block(occ, 'GROUP_NO', 'NB_POINTS COOR_ORIG COOR_EXTR ' // &
                'GROUP_NO_ORIG GROUP_NO_EXTR', st)
            if (st%ok() .and. .not. occ%has('GROUP_NO')) call occ%error_at('TYPE', &
                'TYPE=''GROUP_NO'' needs GROUP_NO, the ordered nodes of the line', st)
            if (st%ok()) call occ%get_text('GROUP_NO', group, st)
            if (st%failed()) return
            g = find_node_group(mesh, group, st)
            if (st%failed()) then
                call relocate_at(occ, 'GROUP_NO', st)
                return
            end if
            nodes = nodes_of_group(mesh, g)
            if (size(nodes) == 0) then
                call occ%error_at('GROUP_NO', 'group ' // group // ' has no node', st)
                return
            end if
            line%x = mesh%coords(:, nodes)
            line%label = group
        end select
        if (occ%has('INTITULE')) then
            call occ%get_text('INTITULE', text, st)
            if (st%failed()) return
            line%label = text
        end if
        call read_frame(occ, mesh, line, st)
        if (st%ok()) call read_quantity(occ, line, st)
    end subroutine read_line

    !> INVARIANT, ELEM_PRINCIPAUX, TRAC_NOR, TRAC_DIR (+ DIRECTION), else the components;
    !> the catalog's rules make them exclusive and give TRAC_* their NOM_CMP.
    subroutine read_quantity(occ, line, st)
        type(keyword_set_t), intent(in) :: occ
        type(line_t), intent(inout) :: line
        type(status_t), intent(inout) :: st
        real(dp), allocatable :: v(:)
        if (occ%has('INVARIANT')) then
            line%quantity = Q_INVARIANTS
        else if (occ%has('ELEM_PRINCIPAUX')) then
            line%quantity = Q_PRINCIPAL
        else if (occ%has('TRAC_NOR')) then
            line%quantity = Q_TRAC_NOR
        else if (occ%has('TRAC_DIR')) then
            line%quantity = Q_TRAC_DIR
            call occ%get_reals('DIRECTION', v, st)
            if (st%failed()) return
            if (size(v) < 2 .or. size(v) > 3) then
                call occ%error_at('DIRECTION', 'DIRECTION is the direction of the ' // &
                    'traction: 2 or 3 components', st)
                return
            end if
            line%direction(1:size(v)) = v
            ! components below 1e-6 count 0, as POST_RELEVE_T's rvpstd takes them
            where (abs(line%direction) < 1.0e-6_dp) line%direction = 0.0_dp
        end if
    end subroutine read_quantity

    !> REPERE: UTILISATEUR (ANGL_NAUT), LOCAL (on a SEGMENT its direction and VECT_Y; on a
    !> GROUP_NO the path's tangents, VECT_Y in 3D), CYLINDRIQUE (ORIGINE, AXE_Z in 3D),
    !> POLAIRE (read at each point by POST_RELEVE_T's polar frame): lign_coupe_frames.
    subroutine read_frame(occ, mesh, line, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        type(line_t), intent(inout) :: line
        type(status_t), intent(inout) :: st
        real(dp), allocatable :: v(:)
        logical :: ok
        integer :: n
        call occ%get_text('REPERE', line%frame, st)
        if (st%failed()) return
        select case (line%frame)
        case ('UTILISATEUR')
            if (.not. occ%has('ANGL_NAUT')) then
                call occ%error_at('REPERE', 'REPERE=''UTILISATEUR'' needs ANGL_NAUT, the ' // &
                    'frame''s nautical angles in degrees', st)
                return
            end if
            call occ%get_reals('ANGL_NAUT', v, st)
            if (st%failed()) return
            line%angles = v(1:3)
        case ('LOCAL')
            if (line%kind == 'GROUP_NO' .and. mesh%dim == 2) return     ! y = z x t
            if (.not. occ%has('VECT_Y')) then
                call occ%error_at('REPERE', 'REPERE=''LOCAL'' needs VECT_Y, the direction ' // &
                    'of the local y axis', st)
                return
            end if
            call occ%get_reals('VECT_Y', v, st)
            if (st%failed()) return
            line%vect_y(1:min(size(v), mesh%dim)) = v(1:min(size(v), mesh%dim))
            if (.not. norm2(line%vect_y) >= LOCAL_EPSILON) then
                call occ%error_at('VECT_Y', 'VECT_Y has no direction (its length is 0)', st)
                return
            end if
            if (line%kind == 'GROUP_NO') return                        ! per point
            n = size(line%x, 2)
            call segment_local_angles(line%x(:, 1), line%x(:, n), line%vect_y, mesh%dim, &
                line%angles, ok)
            if (.not. ok) call occ%error_at('VECT_Y', 'VECT_Y is along the line: it does ' // &
                'not make a frame with it', st)
        case ('CYLINDRIQUE')
            if (.not. occ%has('ORIGINE')) then
                call occ%error_at('REPERE', 'REPERE=''CYLINDRIQUE'' needs ORIGINE, a point ' // &
                    'of the axis', st)
                return
            end if
            call occ%get_reals('ORIGINE', v, st)
            if (st%failed()) return
            if (size(v) /= mesh%dim) then
                call occ%error_at('ORIGINE', 'the mesh is ' // to_text(int(mesh%dim, i4)) // &
                    '-dimensional: ORIGINE has ' // to_text(int(mesh%dim, i4)) // &
                    ' coordinates', st)
                return
            end if
            line%origin(1:size(v)) = v
            line%axis = [0.0_dp, 0.0_dp, 1.0_dp]
            if (mesh%dim == 3) then
                if (.not. occ%has('AXE_Z')) then
                    call occ%error_at('REPERE', 'REPERE=''CYLINDRIQUE'' in a 3D mesh ' // &
                        'needs AXE_Z, the direction of the axis', st)
                    return
                end if
                call occ%get_reals('AXE_Z', v, st)
                if (st%failed()) return
                if (.not. norm2(v) >= LOCAL_EPSILON) then
                    call occ%error_at('AXE_Z', 'AXE_Z has no direction (its length is 0)', st)
                    return
                end if
                line%axis = v / norm2(v)
            end if
        end select
    end subroutine read_frame

    !> The keywords and values of LIGN_COUPE parasol does not build (module header).
    subroutine refuse_unbuilt(occ, kind, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: kind
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: text
        character(len=*), parameter :: KEYS(3) = [character(len=10) :: 'RESULTANTE', &
            'MOMENT', 'CENTRE']
        integer :: k
        if (kind == 'ARC' .or. kind == 'GROUP_MA') then
            call occ%error_at('TYPE', 'TYPE=''' // kind // ''' is not built by parasol: ' // &
                'SEGMENT and GROUP_NO are', st, STATUS_NOT_IMPLEMENTED)
            return
        end if
        call occ%get_text('OPERATION', text, st)
        if (st%ok() .and. text /= 'EXTRACTION') call occ%error_at('OPERATION', &
            'OPERATION=''' // text // ''' is not built by MACR_LIGN_COUPE in parasol: ' // &
            'EXTRACTION is', st, STATUS_NOT_IMPLEMENTED)
        do k = 1, size(KEYS)
            if (st%failed()) return
            if (occ%has(trim(KEYS(k)))) call occ%error_at(trim(KEYS(k)), trim(KEYS(k)) // &
                ' is not built by MACR_LIGN_COUPE in parasol: the components (NOM_CMP), ' // &
                'INVARIANT, ELEM_PRINCIPAUX, TRAC_NOR and TRAC_DIR are', &
                st, STATUS_NOT_IMPLEMENTED)
        end do
    end subroutine refuse_unbuilt

    !> Code_Aster's blocks: keywords of another TYPE are refused.
    subroutine check_block(occ, kind, others, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: kind, others
        type(status_t), intent(inout) :: st
        integer :: a, b
        a = 1
        do while (a <= len(others) .and. st%ok())
            b = index(others(a:) // ' ', ' ') + a - 2
            if (b >= a) then
                if (occ%has(others(a:b))) call occ%error_at(others(a:b), others(a:b) // &
                    ' does not go with TYPE=''' // kind // '''', st)
            end if
            a = b + 2
        end do
    end subroutine check_block

    !> An end of a segment: coordinates (2 or 3, the third 0) or the node of a group.
    subroutine end_point(occ, mesh, coor_key, group_key, p, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: coor_key, group_key
        real(dp), intent(out) :: p(3)
        type(status_t), intent(inout) :: st
        real(dp), allocatable :: v(:)
        character(len=:), allocatable :: group
        integer(i4), allocatable :: nodes(:)
        integer(i4) :: g
        p = 0.0_dp
        if (occ%has(coor_key) .eqv. occ%has(group_key)) then
            call occ%error_at('TYPE', 'give one of ' // coor_key // ' and ' // group_key, st)
            return
        end if
        if (occ%has(coor_key)) then
            call occ%get_reals(coor_key, v, st)
            if (st%ok() .and. size(v) == 2 .and. mesh%dim == 3) call occ%error_at(coor_key, &
                'the mesh is three-dimensional: give 3 coordinates', st)
            if (st%ok()) p(1:size(v)) = v
            return
        end if
        call occ%get_text(group_key, group, st)
        if (st%failed()) return
        g = find_node_group(mesh, group, st)
        if (st%failed()) then
            call relocate_at(occ, group_key, st)
            return
        end if
        nodes = nodes_of_group(mesh, g)
        if (size(nodes) /= 1) then
            call occ%error_at(group_key, 'group ' // group // ' has ' // &
                to_text(size(nodes, kind=i4)) // ' nodes: the end of a segment is one', st)
            return
        end if
        p = mesh%coords(:, nodes(1))
    end subroutine end_point

end module lign_coupe_lines
