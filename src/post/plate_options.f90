!> CALC_CHAMP's options on DKT/DKQ plate cells (Code_Aster's MEDKTR3/MEDKQU4; R3.07.03),
!> the values of one cell at given reference points, in the cell's user frame
!> (element_plate_fields):
!>  PLATE_STRESS  SIXX SIYY SIZZ SIXY SIXZ SIYZ at each sub-point: 3 per layer (INF, MOY,
!>                SUP, layers of equal thickness from the bottom face), s = (Dm/h)(e + z k),
!>                SIZZ = 0, the transverse shear parabolic over the thickness
!>                (6/h^3)(h^2/4 - z^2) T (Code_Aster dkqsie / dktsie);
!>  PLATE_STRAIN  EPXX EPYY EPZZ EPXY EPXZ EPYZ at each sub-point: e + z k as a tensor
!>                (EPXY half the shear), EPZZ = 0, EPXZ EPYZ = T / (2 * 5/6 G h);
!>  PLATE_FORCES  NXX NYY NXY MXX MYY MXY QX QY: N = Dm e, M = Df k, Q = T;
!>  PLATE_GENERAL EXX EYY EXY KXX KYY KXY GAX GAY: e, k as tensors (EXY, KXY half the
!>                engineering values), GAX GAY = T / (2 * 5/6 G h) (Code_Aster dkqedg).
!> The points are Code_Aster's (element_gauss_families): RIGI (FPG4 on QUAD4, FPG3 on
!> TRIA3) for ELGA, the cell's nodes (NOEU) where Code_Aster evaluates at the nodes.
module plate_options
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use mesh_types, only: mesh_t, cell_label, CELL_TRIA3, CELL_QUAD4
    use model_dof_numbering, only: dof_numbering_t, N_COMPONENTS
    use model_material, only: material_field_t, material_of_cell
    use model_cara_elem, only: cara_elem_t
    use element_plate, only: plate_local_frame
    use element_kirchhoff_bending, only: kirchhoff_rotation_map, MAP_ROWS, MAP_COLS
    use element_plate_fields, only: plate_point_strains, plate_point_shear, plate_user_turn, &
        turn_plate_tensor, turn_plate_vector, plate_rigidities
    use model_plate_section, only: plate_section_t
    use assembly_plate_section, only: plate_cell_section
    implicit none
    private

    integer(i4), parameter, public :: PLATE_STRESS = 1, PLATE_STRAIN = 2, PLATE_FORCES = 3, &
        PLATE_GENERAL = 4
    !> The components of each kind of value (module header).
    character(len=*), parameter, public :: PLATE_STRESS_CMPS = 'SIXX SIYY SIZZ SIXY SIXZ SIYZ'
    character(len=*), parameter, public :: PLATE_STRAIN_CMPS = 'EPXX EPYY EPZZ EPXY EPXZ EPYZ'
    character(len=*), parameter, public :: PLATE_FORCES_CMPS = 'NXX NYY NXY MXX MYY MXY QX QY'
    character(len=*), parameter, public :: PLATE_GENERAL_CMPS = 'EXX EYY EXY KXX KYY KXY GAX GAY'

    !> What a cell's values need, prepared once per cell.
    type, public :: plate_cell_t
        integer(i4) :: nn = 0
        real(dp) :: rot(3, 3) = 0.0_dp, xy(2, 4) = 0.0_dp
        real(dp) :: c = 1.0_dp, s = 0.0_dp        !< the turn to the user frame
        real(dp) :: thickness = 0.0_dp, dm(3, 3) = 0.0_dp, df(3, 3) = 0.0_dp, dc = 0.0_dp
        integer(i4) :: layers = 1
        real(dp) :: ul(24) = 0.0_dp               !< local displacements
        !> the section in the element's axes (model_plate_section, elem's): a centred
        !> isotropic section (`homogeneous`) takes dm, df, dc above as before; the others
        !> (ELAS_COQUE, laminates, EXCENTREMENT) its coupling, shear rigidity and layers
        logical :: homogeneous = .true.
        type(plate_section_t) :: section
        !> thermal strains (3 layers, points) at the sub-points of the points asked for
        !> (assembly_varc, elem's), when the cell has some: the stresses and forces leave
        !> them out (sigma = D (e + z k - eps_th), N = Dm e - int D eps_th, ...)
        real(dp), allocatable :: eps_th(:, :)
        !> the cell's rotation map (element_kirchhoff_bending), made once for all its points
        real(dp) :: map_x(MAP_ROWS, MAP_COLS), map_y(MAP_ROWS, MAP_COLS)
    end type plate_cell_t

    public :: plate_prepare, plate_values, plate_value_count

contains

    !> Values per point of a kind: per sub-point for stresses and strains.
    pure integer(i4) function plate_value_count(kind, layers) result(n)
        integer(i4), intent(in) :: kind, layers
        select case (kind)
        case (PLATE_STRESS, PLATE_STRAIN)
            n = 6 * 3 * layers
        case default
            n = 8
        end select
    end function plate_value_count

    !> Prepares a plate cell: frame, user turn, rigidities, local displacements.
    !>  u  : in, displacements as an equation vector of `dofs`
    !>  st : STATUS_MODEL_ERROR naming the cell (a degenerate cell, a direction normal to
    !>       it, a material without ELAS)
    subroutine plate_prepare(mesh, dofs, cara, materials, cell, u, pc, st)
        type(mesh_t), intent(in) :: mesh
        type(dof_numbering_t), intent(in) :: dofs
        type(cara_elem_t), intent(in) :: cara
        type(material_field_t), intent(in) :: materials
        integer(i4), intent(in) :: cell
        real(dp), intent(in) :: u(:)
        type(plate_cell_t), intent(out) :: pc
        type(status_t), intent(out) :: st
        real(dp) :: coords(3, 4), ue(24)
        integer(i4) :: i, k, node, m, eq
        pc%nn = mesh%cell_ptr(cell + 1) - mesh%cell_ptr(cell)
        if (mesh%cell_type(cell) /= CELL_TRIA3 .and. mesh%cell_type(cell) /= CELL_QUAD4) then
            call set_error(st, STATUS_MODEL_ERROR, cell_label(mesh, cell) // ': a DKT ' // &
                'plate is a TRIA3 or a QUAD4')
            return
        end if
        do i = 1, pc%nn
            node = mesh%cell_nodes(mesh%cell_ptr(cell) + i - 1)
            coords(:, i) = mesh%coords(:, node)
            do k = 1, N_COMPONENTS
                eq = dofs%equation(k, node)
                ue(6 * i - 6 + k) = 0.0_dp
                if (eq > 0) ue(6 * i - 6 + k) = u(eq)
            end do
        end do
        call plate_local_frame(coords(:, 1:pc%nn), pc%nn, pc%rot, pc%xy(:, 1:pc%nn), st)
        if (st%ok()) call plate_user_turn(pc%rot, cara%coque_direction(:, cell), pc%c, &
            pc%s, st)
        if (st%failed()) then
            st%message = cell_label(mesh, cell) // ': ' // st%message
            return
        end if
        call kirchhoff_rotation_map(pc%xy(:, 1:pc%nn), pc%nn, pc%map_x, pc%map_y)
        do i = 1, 2 * pc%nn                  ! translations and rotations to the local frame
            pc%ul(3 * i - 2:3 * i) = matmul(pc%rot, ue(3 * i - 2:3 * i))
        end do
        m = material_of_cell(materials, cell)
        if (m == 0) then
            call set_error(st, STATUS_MODEL_ERROR, cell_label(mesh, cell) // ' has no ' // &
                'material: CALC_CHAMP needs its ELAS (give CHAM_MATER)')
            return
        end if
        pc%thickness = cara%thickness(cell)
        if (.not. pc%thickness > 0.0_dp) then
            call set_error(st, STATUS_MODEL_ERROR, cell_label(mesh, cell) // ' has no ' // &
                'thickness: CALC_CHAMP needs its COQUE (give CARA_ELEM)')
            return
        end if
        call plate_cell_section(mesh, materials, cara, cell, pc%rot, pc%section, st)
        if (st%failed()) return
        pc%layers = pc%section%layers
        pc%homogeneous = pc%section%isotropic .and. .not. pc%section%coupled
        if (pc%homogeneous) then
            call plate_rigidities(pc%section%young, pc%section%nu, pc%thickness, pc%dm, &
                pc%df, pc%dc)
        else
            pc%dm = pc%section%dm
            pc%df = pc%section%df
            pc%dc = pc%section%dc(1, 1)
        end if
    end subroutine plate_prepare

    !> The values of `kind` at the np points xi(:, 1:np) of a prepared cell, point by point
    !> (sub-point by sub-point, component by component): values(1 : np *
    !> plate_value_count(kind, layers)).
    subroutine plate_values(pc, kind, xi, np, values)
        type(plate_cell_t), intent(in) :: pc
        integer(i4), intent(in) :: kind, np
        real(dp), intent(in) :: xi(2, np)
        real(dp), intent(out) :: values(:)
        real(dp) :: e(3), k(3), t(2), det, h, z, shape, a(3), v(2), layer_h, n0(3), m0(3)
        integer(i4) :: p, lay, level, base, nv
        if (.not. pc%homogeneous) then
            call section_values(pc, kind, xi, np, values)
            return
        end if
        nv = plate_value_count(kind, pc%layers)
        h = pc%thickness
        layer_h = h / real(pc%layers, dp)
        do p = 1, np
            call plate_point_strains(pc%xy(:, 1:pc%nn), pc%nn, pc%ul(1:6 * pc%nn), xi(:, p), &
                e, k, det, pc%map_x, pc%map_y)
            call plate_point_shear(pc%xy(:, 1:pc%nn), pc%nn, pc%ul(1:6 * pc%nn), pc%df, &
                xi(:, p), t, map_x=pc%map_x, map_y=pc%map_y)
            base = (p - 1) * nv
            select case (kind)
            case (PLATE_FORCES)
                call thermal_resultants(p, n0, m0)
                values(base + 1:base + 3) = turn_plate_tensor(pc%c, pc%s, &
                    matmul(pc%dm, e) - n0)
                values(base + 4:base + 6) = turn_plate_tensor(pc%c, pc%s, &
                    matmul(pc%df, k) - m0)
                values(base + 7:base + 8) = turn_plate_vector(pc%c, pc%s, t)
            case (PLATE_GENERAL)
                values(base + 1:base + 3) = turn_plate_tensor(pc%c, pc%s, &
                    [e(1), e(2), e(3) / 2.0_dp])
                values(base + 4:base + 6) = turn_plate_tensor(pc%c, pc%s, &
                    [k(1), k(2), k(3) / 2.0_dp])
                values(base + 7:base + 8) = turn_plate_vector(pc%c, pc%s, t / pc%dc / 2.0_dp)
            case (PLATE_STRESS, PLATE_STRAIN)
                do lay = 1, pc%layers
                    do level = 1, 3              ! INF, MOY, SUP
                        z = -h / 2.0_dp + (lay - 1) * layer_h + (level - 1) * layer_h / 2.0_dp
                        if (kind == PLATE_STRESS) then
                            a = e + z * k
                            if (allocated(pc%eps_th)) a(1:2) = a(1:2) - &
                                pc%eps_th(3 * lay - 3 + level, p)
                            a = matmul(pc%dm, a) / h
                            shape = 6.0_dp / h**3 * (h * h / 4.0_dp - z * z)
                            v = shape * t
                        else
                            a = e + z * k
                            a(3) = a(3) / 2.0_dp
                            v = t / pc%dc / 2.0_dp
                        end if
                        a = turn_plate_tensor(pc%c, pc%s, a)
                        v = turn_plate_vector(pc%c, pc%s, v)
                        values(base + 1:base + 6) = [a(1), a(2), 0.0_dp, a(3), v(1), v(2)]
                        base = base + 6
                    end do
                end do
            end select
        end do
    contains
        ! N0 = int D eps_th dz, M0 = int D eps_th z dz at point q (Simpson per layer).
        subroutine thermal_resultants(q, n0, m0)
            integer(i4), intent(in) :: q
            real(dp), intent(out) :: n0(3), m0(3)
            real(dp) :: unit(3), zl, wl
            integer(i4) :: l, j
            n0 = 0.0_dp
            m0 = 0.0_dp
            if (.not. allocated(pc%eps_th)) return
            unit = matmul(pc%dm, [1.0_dp, 1.0_dp, 0.0_dp]) / pc%thickness
            do l = 1, pc%layers
                do j = 1, 3
                    zl = -pc%thickness / 2.0_dp + (l - 1) * layer_h + (j - 1) * layer_h / 2.0_dp
                    wl = layer_h * merge(4.0_dp, 1.0_dp, j == 2) / 6.0_dp
                    n0 = n0 + unit * wl * pc%eps_th(3 * l - 3 + j, q)
                    m0 = m0 + unit * wl * zl * pc%eps_th(3 * l - 3 + j, q)
                end do
            end do
        end subroutine thermal_resultants
    end subroutine plate_values

    !> plate_values of a cell whose section is not a centred isotropic one (ELAS_COQUE,
    !> laminates, EXCENTREMENT; model_plate_section):
    !>  N = Dm e + Dmf k, M = Dmf e + Df k (less the thermal resultants);
    !>  in-plane stresses Q_layer (e + z k - eps_th), z from the reference surface at the
    !>  layer's INF, MOY, SUP (ELAS_COQUE: Dm / h through the thickness, as Code_Aster's
    !>  dkqsie);
    !>  transverse shear stresses: 6/h^3 (h^2/4 - zeta^2) T for one material (zeta from the
    !>  middle of the section, T from Df), a laminate's from equilibrium with its bending
    !>  stresses, s_xz(z) = -int_bottom^z zeta (Q(1,:) dk/dx + Q(3,:) dk/dy) dzeta;
    !>  shear strains Dc^-1 T / 2.
    subroutine section_values(pc, kind, xi, np, values)
        type(plate_cell_t), intent(in) :: pc
        integer(i4), intent(in) :: kind, np
        real(dp), intent(in) :: xi(2, np)
        real(dp), intent(out) :: values(:)
        real(dp) :: e(3), k(3), t(2), det, z, a(3), v(2), n0(3), m0(3), dk(3, 2), g(2)
        real(dp) :: dci(2, 2), q(3, 3), zb, zt, mid, ddet, acc(2), zs
        integer(i4) :: p, lay, level, base, nv
        nv = plate_value_count(kind, pc%layers)
        associate (sec => pc%section)
            ddet = sec%dc(1, 1) * sec%dc(2, 2) - sec%dc(1, 2) * sec%dc(2, 1)
            dci = 0.0_dp
            if (abs(ddet) > 0.0_dp) then
                dci(1, :) = [sec%dc(2, 2), -sec%dc(1, 2)] / ddet
                dci(2, :) = [-sec%dc(2, 1), sec%dc(1, 1)] / ddet
            end if
            mid = sec%offset
            do p = 1, np
                call plate_point_strains(pc%xy(:, 1:pc%nn), pc%nn, pc%ul(1:6 * pc%nn), &
                    xi(:, p), e, k, det, pc%map_x, pc%map_y)
                call plate_point_shear(pc%xy(:, 1:pc%nn), pc%nn, pc%ul(1:6 * pc%nn), sec%df, &
                    xi(:, p), t, dk, pc%map_x, pc%map_y)
                g = matmul(dci, t)
                base = (p - 1) * nv
                select case (kind)
                case (PLATE_FORCES)
                    call section_thermal(pc, p, n0, m0)
                    values(base + 1:base + 3) = turn_plate_tensor(pc%c, pc%s, &
                        matmul(sec%dm, e) + matmul(sec%dmf, k) - n0)
                    values(base + 4:base + 6) = turn_plate_tensor(pc%c, pc%s, &
                        matmul(sec%dmf, e) + matmul(sec%df, k) - m0)
                    values(base + 7:base + 8) = turn_plate_vector(pc%c, pc%s, t)
                case (PLATE_GENERAL)
                    values(base + 1:base + 3) = turn_plate_tensor(pc%c, pc%s, &
                        [e(1), e(2), e(3) / 2.0_dp])
                    values(base + 4:base + 6) = turn_plate_tensor(pc%c, pc%s, &
                        [k(1), k(2), k(3) / 2.0_dp])
                    values(base + 7:base + 8) = turn_plate_vector(pc%c, pc%s, g / 2.0_dp)
                case (PLATE_STRESS, PLATE_STRAIN)
                    acc = 0.0_dp                 ! the shear flow from the bottom face
                    do lay = 1, pc%layers
                        call layer_of(pc, lay, zb, zt, q)
                        do level = 1, 3              ! INF, MOY, SUP
                            z = zb + real(level - 1, dp) * (zt - zb) / 2.0_dp
                            a = e + z * k
                            if (kind == PLATE_STRESS) then
                                if (allocated(pc%eps_th)) a(1:2) = a(1:2) - &
                                    pc%eps_th(3 * lay - 3 + level, p)
                                a = matmul(q, a)
                                zs = z - mid
                                v = acc - shear_flow(q, dk, zb - mid, zs)
                                if (.not. sec%laminate) v = 6.0_dp / pc%thickness**3 * &
                                    (pc%thickness**2 / 4.0_dp - zs * zs) * t
                            else
                                a(3) = a(3) / 2.0_dp
                                v = g / 2.0_dp
                            end if
                            a = turn_plate_tensor(pc%c, pc%s, a)
                            v = turn_plate_vector(pc%c, pc%s, v)
                            values(base + 1:base + 6) = [a(1), a(2), 0.0_dp, a(3), v(1), v(2)]
                            base = base + 6
                        end do
                        acc = acc - shear_flow(q, dk, zb - mid, zt - mid)
                    end do
                end select
            end do
        end associate
    end subroutine section_values

    ! The bottom and top faces (from the reference surface) and the stiffness of layer lay:
    ! a laminate's own, else even layers of the thickness around the middle (offset) with
    ! Dm / h.
    pure subroutine layer_of(pc, lay, zb, zt, q)
        type(plate_cell_t), intent(in) :: pc
        integer(i4), intent(in) :: lay
        real(dp), intent(out) :: zb, zt, q(3, 3)
        real(dp) :: h
        if (allocated(pc%section%z) .and. allocated(pc%section%q)) then
            zb = pc%section%z(lay)
            zt = pc%section%z(lay + 1)
            q = pc%section%q(:, :, lay)
            return
        end if
        h = pc%thickness
        zb = pc%section%offset - h / 2.0_dp + real(lay - 1, dp) * h / real(pc%layers, dp)
        zt = zb + h / real(pc%layers, dp)
        q = pc%section%dm / h
    end subroutine layer_of

    ! int_za^zb zeta (Q(1,:) dk(:,1) + Q(3,:) dk(:,2), Q(3,:) dk(:,1) + Q(2,:) dk(:,2)) dzeta
    pure function shear_flow(q, dk, za, zb) result(f)
        real(dp), intent(in) :: q(3, 3), dk(3, 2), za, zb
        real(dp) :: f(2), w
        w = (zb * zb - za * za) / 2.0_dp
        f(1) = w * (dot_product(q(1, :), dk(:, 1)) + dot_product(q(3, :), dk(:, 2)))
        f(2) = w * (dot_product(q(3, :), dk(:, 1)) + dot_product(q(2, :), dk(:, 2)))
    end function shear_flow

    ! The thermal resultants N0, M0 of a non-homogeneous section at point q (about the
    ! reference surface; Simpson per layer with the layer's stiffness).
    subroutine section_thermal(pc, q, n0, m0)
        type(plate_cell_t), intent(in) :: pc
        integer(i4), intent(in) :: q
        real(dp), intent(out) :: n0(3), m0(3)
        real(dp) :: zb, zt, qq(3, 3), zl, wl, unit(3)
        integer(i4) :: l, j
        n0 = 0.0_dp
        m0 = 0.0_dp
        if (.not. allocated(pc%eps_th)) return
        do l = 1, pc%layers
            call layer_of(pc, l, zb, zt, qq)
            unit = matmul(qq, [1.0_dp, 1.0_dp, 0.0_dp])
            do j = 1, 3
                zl = zb + real(j - 1, dp) * (zt - zb) / 2.0_dp
                wl = (zt - zb) * merge(4.0_dp, 1.0_dp, j == 2) / 6.0_dp
                n0 = n0 + unit * wl * pc%eps_th(3 * l - 3 + j, q)
                m0 = m0 + unit * wl * zl * pc%eps_th(3 * l - 3 + j, q)
            end do
        end do
    end subroutine section_thermal

end module plate_options
