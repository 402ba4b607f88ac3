!> Flat shell elements of MODELISATION 'DKT': DKQ on QUAD4 (24x24) and DKT on TRIA3 (18x18).
!>
!> 6 DOF per node in the GLOBAL frame, node by node: (DX, DY, DZ, DRX, DRY, DRZ).
!> Local element = membrane (bilinear Q4, 2x2 Gauss / constant-strain triangle) + discrete
!> Kirchhoff bending (element_kirchhoff_bending) + a fictitious drilling stiffness on the
!> local rotation about the normal: COEF_RIGI_DRZ times the smallest bending-rotation
!> diagonal term (local DRX/DRY) of the element (AFFE_CARA_ELEM/COQUE COEF_RIGI_DRZ,
!> Code_Aster default 1e-5).
!> Isotropic plane-stress material (E, NU), constant thickness h.
!>
!> Local frame (plate_local_frame, see doc/elements.md):
!>   normal n: TRIA3 (x2 - x1) x (x3 - x1); QUAD4 (x3 - x1) x (x4 - x2) (the mean plane of
!>   a warped cell), i.e. the right-hand rule on the node order; local x: side 1 -> 2
!>   projected on the plane; local y = n x local x. Node coordinates are projected on the
!>   plane through the centroid (a warped QUAD4 is treated as its projection; no warping
!>   correction).
module element_plate
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use element_plane, only: plane_elasticity_matrix, plane_stiffness, plane_derivatives
    use element_kirchhoff_bending, only: kirchhoff_bending_stiffness, kirchhoff_bending_b
    use element_quadrature, only: gauss_quad, hammer_tria3
    use mesh_cell_shapes, only: CELL_TRIA3, CELL_QUAD4
    implicit none
    private

    !> No membrane-bending coupling.
    real(dp), parameter :: ZERO_COUPLING(3, 3) = 0.0_dp

    !> Code_Aster's default COEF_RIGI_DRZ (AFFE_CARA_ELEM/COQUE).
    real(dp), parameter, public :: PLATE_COEF_RIGI_DRZ = 1.0e-5_dp

    public :: plate_local_frame, plate_local_stiffness, plate_stiffness, &
        plate_section_stiffness, plate_membrane_b
    public :: plate_internal_forces, plate_forces_from_local, rotate_to_global
    public :: plate_block_size, plate_local_blocks, plate_forces_from_blocks, &
        expand_plate_blocks, plate_section_blocks
    public :: dkq_stiffness, dkt_stiffness

contains

    !> Local frame and in-plane coordinates of a TRIA3 (nn = 3) or QUAD4 (nn = 4) cell.
    !>  coords : in, coords(1:3, nn) global node coordinates
    !>  nn     : in, 3 or 4
    !>  rot    : out, rot(3,3), rows = local x, y, normal in global components
    !>  xy     : out, xy(1:2, nn) node coordinates in the local plane (origin = centroid)
    !>  st     : out, STATUS_MODEL_ERROR if the cell has (nearly) zero area
    subroutine plate_local_frame(coords, nn, rot, xy, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: coords(3, nn)
        real(dp), intent(out) :: rot(3, 3), xy(2, nn)
        type(status_t), intent(out) :: st
        real(dp) :: n(3), ex(3), c(3), size2
        integer(i4) :: i
        rot = 0.0_dp
        xy = 0.0_dp
        if (nn == 3) then
            n = cross(coords(:, 2) - coords(:, 1), coords(:, 3) - coords(:, 1))
        else
            n = cross(coords(:, 3) - coords(:, 1), coords(:, 4) - coords(:, 2))
        end if
        size2 = sum((coords(:, 2) - coords(:, 1))**2) + sum((coords(:, nn) - coords(:, 1))**2)
        if (.not. norm2(n) > 1.0e3_dp * epsilon(1.0_dp) * size2) then
            call set_error(st, STATUS_MODEL_ERROR, 'plate cell has zero area ' // &
                '(coincident or aligned nodes): no normal')
            return
        end if
        n = n / norm2(n)
        ex = coords(:, 2) - coords(:, 1)
        ex = ex - dot_product(ex, n) * n
        if (.not. norm2(ex) > 0.0_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'plate cell: side 1-2 is normal ' // &
                'to the mean plane, no local x axis')
            return
        end if
        ex = ex / norm2(ex)
        rot(1, :) = ex
        rot(2, :) = cross(n, ex)
        rot(3, :) = n
        c = sum(coords, dim=2) / real(nn, dp)
        do i = 1, nn
            xy(:, i) = matmul(rot(1:2, :), coords(:, i) - c)
        end do
    end subroutine plate_local_frame

    !> Stiffness in the local frame, DOF order (u, v, w, thx, thy, thz) per node, of an
    !> isotropic plate (E, NU, EPAIS): plate_section_stiffness with Dm = h Q, Df = h^3/12 Q.
    !>  xy : in, local coordinates; nn : in, 3 or 4; young, nu, thickness : in, material
    !>  coef_drz : in, COEF_RIGI_DRZ (PLATE_COEF_RIGI_DRZ by default)
    !>  kl : out, kl(6nn, 6nn); st : out, material, thickness or geometry error
    subroutine plate_local_stiffness(xy, nn, young, nu, thickness, coef_drz, kl, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: xy(2, nn), young, nu, thickness, coef_drz
        real(dp), intent(out) :: kl(6 * nn, 6 * nn)
        type(status_t), intent(out) :: st
        real(dp) :: dmat(3, 3)
        kl = 0.0_dp
        if (.not. thickness > 0.0_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'COQUE/EPAIS must be > 0')
            return
        end if
        call plane_elasticity_matrix(young, nu, .false., dmat, st)
        if (st%failed()) return
        call plate_section_stiffness(xy, nn, thickness * dmat, ZERO_COUPLING, &
            (thickness**3 / 12.0_dp) * dmat, coef_drz, kl, st)
    end subroutine plate_local_stiffness

    !> Stiffness in the local frame, DOF order (u, v, w, thx, thy, thz) per node, of a plate
    !> section given by its rigidities in the element's axes (model_plate_section): the
    !> membrane (Dm; QUAD4 2x2 Gauss, TRIA3 constant strain), the discrete Kirchhoff bending
    !> (Df), their coupling int Bm^t Dmf Bb over the same points as the bending (when Dmf is
    !> not zero), and the drilling term COEF_RIGI_DRZ times the smallest bending-rotation
    !> diagonal term.
    !>  kl : out, kl(6nn, 6nn); st : out, a degenerate cell
    subroutine plate_section_stiffness(xy, nn, dm, dmf, df, coef_drz, kl, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: xy(2, nn), dm(3, 3), dmf(3, 3), df(3, 3), coef_drz
        real(dp), intent(out) :: kl(6 * nn, 6 * nn)
        type(status_t), intent(out) :: st
        real(dp) :: km(2 * nn, 2 * nn), kb(3 * nn, 3 * nn), kmb(2 * nn, 3 * nn), kdrz
        integer(i4) :: im(2 * nn), ib(3 * nn), i
        kl = 0.0_dp
        if (nn == 4) then
            call plane_stiffness(CELL_QUAD4, xy, dm, km, st)
        else
            call membrane_tria3_stiffness(xy, dm, km, st)
        end if
        if (st%failed()) return
        call kirchhoff_bending_stiffness(xy, nn, df, kb, st)
        if (st%failed()) return
        call block_indices(nn, im, ib)
        kl(im, im) = km
        kl(ib, ib) = kb
        if (any(abs(dmf) > 0.0_dp)) then
            call plate_coupling_stiffness(xy, nn, dmf, kmb, st)
            if (st%failed()) return
            kl(im, ib) = kmb
            kl(ib, im) = transpose(kmb)
        end if
        kdrz = huge(1.0_dp)
        do i = 1, nn
            kdrz = min(kdrz, kb(3 * i - 1, 3 * i - 1), kb(3 * i, 3 * i))
        end do
        do i = 1, nn
            kl(6 * i, 6 * i) = coef_drz * kdrz
        end do
    end subroutine plate_section_stiffness

    !> The membrane-bending coupling block int Bm^t Dmf Bb dA (u, v rows; w, thx, thy
    !> columns) at the bending's points (Hammer 3 points / 2x2 Gauss).
    subroutine plate_coupling_stiffness(xy, nn, dmf, kmb, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: xy(2, nn), dmf(3, 3)
        real(dp), intent(out) :: kmb(2 * nn, 3 * nn)
        type(status_t), intent(out) :: st
        real(dp) :: xg(2, 4), wg(4), bb(3, 3 * nn), bm(3, 2 * nn), det, detb
        integer(i4) :: g, ng
        kmb = 0.0_dp
        if (nn == 3) then
            call hammer_tria3(xg, wg)
            ng = 3
        else
            call gauss_quad(2_i4, xg, wg)
            ng = 4
        end if
        do g = 1, ng
            call kirchhoff_bending_b(xy, nn, xg(:, g), bb, detb)
            call plate_membrane_b(xy, nn, xg(:, g), bm, det)
            if (.not. det > 0.0_dp .or. .not. detb > 0.0_dp) then
                call set_error(st, STATUS_MODEL_ERROR, 'plate cell has a non-positive ' // &
                    'Jacobian (degenerate or non-convex cell)')
                return
            end if
            kmb = kmb + matmul(transpose(bm), matmul(dmf, bb)) * (det * wg(g))
        end do
    end subroutine plate_coupling_stiffness

    !> The membrane strain-displacement matrix (u, v per node; xx, yy, xy engineering) of a
    !> TRIA3 (linear) or QUAD4 (bilinear) plate cell at reference point xi ((L2, L3) on the
    !> triangle, [-1, 1]^2 on the quadrilateral).
    !>  det : out, the Jacobian determinant (bm = 0 when it is 0)
    pure subroutine plate_membrane_b(xy, nn, xi, bm, det)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: xy(2, nn), xi(2)
        real(dp), intent(out) :: bm(3, 2 * nn), det
        real(dp) :: n(4), dxy(2, 4)
        integer(i4) :: a
        call plane_derivatives(merge(CELL_TRIA3, CELL_QUAD4, nn == 3), xy, xi(1), xi(2), &
            n, dxy, det)
        bm = 0.0_dp
        do a = 1, nn
            bm(1, 2 * a - 1) = dxy(1, a)
            bm(2, 2 * a) = dxy(2, a)
            bm(3, 2 * a - 1) = dxy(2, a)
            bm(3, 2 * a) = dxy(1, a)
        end do
    end subroutine plate_membrane_b

    !> Global stiffness of a DKT (nn = 3) or DKQ (nn = 4) element.
    !>  coords : in, coords(1:3, nn) global coordinates; nn : in, 3 or 4
    !>  young, nu, thickness, coef_drz : in, material, EPAIS, COEF_RIGI_DRZ
    !>  ke : out, ke(6nn, 6nn) in the global frame (DX, DY, DZ, DRX, DRY, DRZ per node)
    !>  st : out, geometry/material error
    subroutine plate_stiffness(coords, nn, young, nu, thickness, coef_drz, ke, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: coords(3, nn), young, nu, thickness, coef_drz
        real(dp), intent(out) :: ke(6 * nn, 6 * nn)
        type(status_t), intent(out) :: st
        real(dp) :: rot(3, 3), xy(2, nn), kl(6 * nn, 6 * nn)
        ke = 0.0_dp
        call plate_frame_and_local_stiffness(coords, nn, young, nu, thickness, coef_drz, &
            rot, xy, kl, st)
        if (st%failed()) return
        call rotate_to_global(rot, 2 * nn, kl, ke)
    end subroutine plate_stiffness

    !> The element frame and the local stiffness of a DKT/DKQ plate (the common first half of
    !> plate_stiffness and plate_internal_forces).
    !>  rot, xy : out, as plate_local_frame; kl : out, kl(6nn, 6nn) in the local frame
    !>  st : out, a cell that is not TRIA3/QUAD4, or a geometry/material error
    subroutine plate_frame_and_local_stiffness(coords, nn, young, nu, thickness, coef_drz, &
                                               rot, xy, kl, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: coords(3, nn), young, nu, thickness, coef_drz
        real(dp), intent(out) :: rot(3, 3), xy(2, nn), kl(6 * nn, 6 * nn)
        type(status_t), intent(out) :: st
        if (nn /= 3 .and. nn /= 4) then
            call set_error(st, STATUS_MODEL_ERROR, 'DKT plates need TRIA3 or QUAD4 cells')
            return
        end if
        call plate_local_frame(coords, nn, rot, xy, st)
        if (st%failed()) return
        call plate_local_stiffness(xy, nn, young, nu, thickness, coef_drz, kl, st)
        if (st%failed()) return
    end subroutine plate_frame_and_local_stiffness

    !> DKQ (QUAD4) global stiffness, 24x24; arguments as plate_stiffness.
    subroutine dkq_stiffness(coords, young, nu, thickness, coef_drz, ke, st)
        real(dp), intent(in) :: coords(3, 4), young, nu, thickness, coef_drz
        real(dp), intent(out) :: ke(24, 24)
        type(status_t), intent(out) :: st
        call plate_stiffness(coords, 4_i4, young, nu, thickness, coef_drz, ke, st)
    end subroutine dkq_stiffness

    !> DKT (TRIA3) global stiffness, 18x18; arguments as plate_stiffness.
    subroutine dkt_stiffness(coords, young, nu, thickness, coef_drz, ke, st)
        real(dp), intent(in) :: coords(3, 3), young, nu, thickness, coef_drz
        real(dp), intent(out) :: ke(18, 18)
        type(status_t), intent(out) :: st
        call plate_stiffness(coords, 3_i4, young, nu, thickness, coef_drz, ke, st)
    end subroutine dkt_stiffness

    !> Internal forces f = K u of a DKT/DKQ element (linear elasticity, global frame).
    !> Computed as f = T^T K_l (T u - u_0), where u_0 is a zero-energy mode of the local
    !> matrix fitted to the element (mean translations, mean local rotations thx, thy and the
    !> matching w, mean in-plane membrane rotation with thz untouched): K_l u_0 = 0, so the
    !> result equals K u, but the large rigid part of a nearly rigid plate no longer goes
    !> through K (entries ~1e11 for SSNL130): the residual's round-off floor drops from
    !> ~1e-6 to round-off of the deformation itself.
    !>  coords, nn, young, nu, thickness, coef_drz : in, as plate_stiffness
    !>  ue : in, ue(6nn) global displacements; fe : out, fe(6nn); st : out, as above
    subroutine plate_internal_forces(coords, nn, young, nu, thickness, coef_drz, ue, fe, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: coords(3, nn), young, nu, thickness, coef_drz, ue(6 * nn)
        real(dp), intent(out) :: fe(6 * nn)
        type(status_t), intent(out) :: st
        real(dp) :: rot(3, 3), xy(2, nn), kl(6 * nn, 6 * nn)
        fe = 0.0_dp
        call plate_frame_and_local_stiffness(coords, nn, young, nu, thickness, coef_drz, &
            rot, xy, kl, st)
        if (st%failed()) return
        call plate_forces_from_local(rot, xy, nn, kl, ue, fe)
    end subroutine plate_internal_forces

    !> The second half of plate_internal_forces, for callers that keep the local frame and
    !> matrix of an element (computed once by plate_local_frame and plate_local_stiffness):
    !> f = T^T K_l (T u - u_0), bit for bit what plate_internal_forces gives.
    !>  rot, xy : in, from plate_local_frame; nn : in, 3 or 4
    !>  kl : in, kl(6nn, 6nn) from plate_local_stiffness
    !>  ue : in, ue(6nn) global displacements; fe : out, fe(6nn) global forces
    pure subroutine plate_forces_from_local(rot, xy, nn, kl, ue, fe)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: rot(3, 3), xy(2, nn), kl(6 * nn, 6 * nn), ue(6 * nn)
        real(dp), intent(out) :: fe(6 * nn)
        real(dp) :: ul(24), fl(24)     ! fixed size (DKQ): no heap temporaries per call
        call vectors_to_local(rot, nn, ue, ul)
        call remove_zero_energy_mode(xy, nn, ul(1:6 * nn))
        call local_matvec(6 * nn, kl, ul, fl)
        call vectors_to_global(rot, nn, fl, fe)
    end subroutine plate_forces_from_local

    !> ul = T ue: the 2nn 3-vectors (translations, rotations) of a plate cell's nodes in
    !> its local frame, sums in ascending order as matmul's (bit for bit the same forces
    !> whichever storage of the local stiffness is used).
    pure subroutine vectors_to_local(rot, nn, ue, ul)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: rot(3, 3), ue(6 * nn)
        real(dp), intent(out) :: ul(:)
        integer(i4) :: i, r, c
        do i = 1, 2 * nn
            do r = 1, 3
                ul(3 * i - 3 + r) = 0.0_dp
                do c = 1, 3
                    ul(3 * i - 3 + r) = ul(3 * i - 3 + r) + rot(r, c) * ue(3 * i - 3 + c)
                end do
            end do
        end do
    end subroutine vectors_to_local

    !> fe = T^T fl: local forces of a plate cell's nodes back to the global frame.
    pure subroutine vectors_to_global(rot, nn, fl, fe)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: rot(3, 3), fl(:)
        real(dp), intent(out) :: fe(6 * nn)
        integer(i4) :: i, r, c
        do i = 1, 2 * nn
            do r = 1, 3
                fe(3 * i - 3 + r) = 0.0_dp
                do c = 1, 3
                    fe(3 * i - 3 + r) = fe(3 * i - 3 + r) + rot(c, r) * fl(3 * i - 3 + c)
                end do
            end do
        end do
    end subroutine vectors_to_global

    !> Terms of the local stiffness stored by blocks (plate_local_blocks): the membrane
    !> block (u, v of every node, (2nn)^2), the bending block (w, thx, thy, (3nn)^2) and the
    !> nn drilling terms: 212 for a DKQ instead of 24^2 = 576 (the other terms are zero);
    !> with `coupled`, the membrane-bending block (2nn x 3nn) after them.
    pure integer(i4) function plate_block_size(nn, coupled)
        integer(i4), intent(in) :: nn
        logical, intent(in), optional :: coupled
        plate_block_size = 13 * nn * nn + nn
        if (present(coupled)) then
            if (coupled) plate_block_size = plate_block_size + 6 * nn * nn
        end if
    end function plate_block_size

    !> The local stiffness of plate_local_stiffness, by blocks (plate_block_size): the
    !> same values, a third of the memory.
    !>  kblk : out, (plate_block_size(nn)): membrane block, bending block (column-major),
    !>         drilling terms
    subroutine plate_local_blocks(xy, nn, young, nu, thickness, coef_drz, kblk, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: xy(2, nn), young, nu, thickness, coef_drz
        real(dp), intent(out) :: kblk(:)
        type(status_t), intent(out) :: st
        real(dp) :: kl(6 * nn, 6 * nn)
        kblk = 0.0_dp
        call plate_local_stiffness(xy, nn, young, nu, thickness, coef_drz, kl, st)
        if (st%failed()) return
        call local_to_blocks(nn, kl, kblk)
    end subroutine plate_local_blocks

    !> plate_section_stiffness by blocks: size(kblk) = plate_block_size(nn, coupled), the
    !> coupling block kept when coupled.
    subroutine plate_section_blocks(xy, nn, dm, dmf, df, coef_drz, kblk, st)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: xy(2, nn), dm(3, 3), dmf(3, 3), df(3, 3), coef_drz
        real(dp), intent(out) :: kblk(:)
        type(status_t), intent(out) :: st
        real(dp) :: kl(6 * nn, 6 * nn)
        kblk = 0.0_dp
        call plate_section_stiffness(xy, nn, dm, dmf, df, coef_drz, kl, st)
        if (st%failed()) return
        call local_to_blocks(nn, kl, kblk)
    end subroutine plate_section_blocks

    ! The blocks of a full local matrix (the coupling block when kblk has room for it).
    pure subroutine local_to_blocks(nn, kl, kblk)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: kl(6 * nn, 6 * nn)
        real(dp), intent(out) :: kblk(:)
        integer(i4) :: im(2 * nn), ib(3 * nn), i, j, k
        call block_indices(nn, im, ib)
        k = 0
        do j = 1, 2 * nn
            do i = 1, 2 * nn
                k = k + 1
                kblk(k) = kl(im(i), im(j))
            end do
        end do
        do j = 1, 3 * nn
            do i = 1, 3 * nn
                k = k + 1
                kblk(k) = kl(ib(i), ib(j))
            end do
        end do
        do i = 1, nn
            kblk(k + i) = kl(6 * i, 6 * i)
        end do
        k = k + nn
        if (size(kblk) < k + 6 * nn * nn) return
        do j = 1, 3 * nn
            do i = 1, 2 * nn
                k = k + 1
                kblk(k) = kl(im(i), ib(j))
            end do
        end do
    end subroutine local_to_blocks

    !> The full local stiffness (6nn x 6nn) of its blocks (plate_local_blocks,
    !> plate_section_blocks).
    pure subroutine expand_plate_blocks(nn, kblk, kl)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: kblk(:)
        real(dp), intent(out) :: kl(6 * nn, 6 * nn)
        integer(i4) :: im(2 * nn), ib(3 * nn), i, j, k
        kl = 0.0_dp
        call block_indices(nn, im, ib)
        k = 0
        do j = 1, 2 * nn
            do i = 1, 2 * nn
                k = k + 1
                kl(im(i), im(j)) = kblk(k)
            end do
        end do
        do j = 1, 3 * nn
            do i = 1, 3 * nn
                k = k + 1
                kl(ib(i), ib(j)) = kblk(k)
            end do
        end do
        do i = 1, nn
            kl(6 * i, 6 * i) = kblk(k + i)
        end do
        k = k + nn
        if (size(kblk) < k + 6 * nn * nn) return
        do j = 1, 3 * nn
            do i = 1, 2 * nn
                k = k + 1
                kl(im(i), ib(j)) = kblk(k)
                kl(ib(j), im(i)) = kblk(k)
            end do
        end do
    end subroutine expand_plate_blocks

    !> plate_forces_from_local with the local stiffness by blocks: the products skip only
    !> the zero terms and keep the order of the others (ascending column), so the forces
    !> are bit for bit those of the full matrix.
    pure subroutine plate_forces_from_blocks(rot, xy, nn, kblk, ue, fe)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: rot(3, 3), xy(2, nn), kblk(:), ue(6 * nn)
        real(dp), intent(out) :: fe(6 * nn)
        real(dp) :: ul(24), fl(24)
        integer(i4) :: im(2 * nn), ib(3 * nn), i, j, k, m
        call vectors_to_local(rot, nn, ue, ul)
        call remove_zero_energy_mode(xy, nn, ul(1:6 * nn))
        call block_indices(nn, im, ib)
        fl(1:6 * nn) = 0.0_dp
        m = 2 * nn
        do j = 1, m
            do i = 1, m
                fl(im(i)) = fl(im(i)) + kblk(i + (j - 1) * m) * ul(im(j))
            end do
        end do
        k = m * m
        m = 3 * nn
        do j = 1, m
            do i = 1, m
                fl(ib(i)) = fl(ib(i)) + kblk(k + i + (j - 1) * m) * ul(ib(j))
            end do
        end do
        k = k + m * m
        do i = 1, nn
            fl(6 * i) = fl(6 * i) + kblk(k + i) * ul(6 * i)
        end do
        k = k + nn
        if (size(kblk) >= k + 6 * nn * nn) then        ! the membrane-bending coupling
            do j = 1, 3 * nn
                do i = 1, 2 * nn
                    k = k + 1
                    fl(im(i)) = fl(im(i)) + kblk(k) * ul(ib(j))
                    fl(ib(j)) = fl(ib(j)) + kblk(k) * ul(im(i))
                end do
            end do
        end if
        call vectors_to_global(rot, nn, fl, fe)
    end subroutine plate_forces_from_blocks

    !> Local DOF of the membrane (u, v) and bending (w, thx, thy) blocks, node by node.
    pure subroutine block_indices(nn, im, ib)
        integer(i4), intent(in) :: nn
        integer(i4), intent(out) :: im(2 * nn), ib(3 * nn)
        integer(i4) :: i
        do i = 1, nn
            im(2 * i - 1:2 * i) = [6 * i - 5, 6 * i - 4]
            ib(3 * i - 2:3 * i) = [6 * i - 3, 6 * i - 2, 6 * i - 1]
        end do
    end subroutine block_indices

    !> fl(1:m) = kl ul(1:m), column by column (the sum over columns in ascending order, as
    !> the library matmul does it), inlined: this is the inner kernel of every iteration.
    pure subroutine local_matvec(m, kl, ul, fl)
        integer(i4), intent(in) :: m
        real(dp), intent(in) :: kl(m, m), ul(:)
        real(dp), intent(out) :: fl(:)
        integer(i4) :: i, j
        fl(1:m) = 0.0_dp
        do j = 1, m
            do i = 1, m
                fl(i) = fl(i) + kl(i, j) * ul(j)
            end do
        end do
    end subroutine local_matvec

    !> Subtracts from local displacements ul (u, v, w, thx, thy, thz per node) a motion that
    !> the local matrix maps to zero: translations t, bending rotation (ox, oy) with
    !> w = ox y - oy x, thx = ox, thy = oy (thx = w,y and thy = -w,x), and an in-plane
    !> rotation oz (u = -oz y, v = oz x, thz unchanged, since the drilling spring is not
    !> rotation invariant). xy are centred on the centroid.
    pure subroutine remove_zero_energy_mode(xy, nn, ul)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: xy(2, nn)
        real(dp), intent(inout) :: ul(6 * nn)
        real(dp) :: t(3), ox, oy, oz, r2
        integer(i4) :: i
        t = 0.0_dp
        ox = 0.0_dp
        oy = 0.0_dp
        oz = 0.0_dp
        r2 = 0.0_dp
        do i = 1, nn
            t = t + ul(6 * i - 5:6 * i - 3)
            ox = ox + ul(6 * i - 2)
            oy = oy + ul(6 * i - 1)
            oz = oz + xy(1, i) * ul(6 * i - 4) - xy(2, i) * ul(6 * i - 5)
            r2 = r2 + xy(1, i)**2 + xy(2, i)**2
        end do
        t = t / real(nn, dp)
        ox = ox / real(nn, dp)
        oy = oy / real(nn, dp)
        if (r2 > 0.0_dp) oz = oz / r2
        do i = 1, nn
            ul(6 * i - 5) = ul(6 * i - 5) - (t(1) - oz * xy(2, i))
            ul(6 * i - 4) = ul(6 * i - 4) - (t(2) + oz * xy(1, i))
            ul(6 * i - 3) = ul(6 * i - 3) - (t(3) + ox * xy(2, i) - oy * xy(1, i))
            ul(6 * i - 2) = ul(6 * i - 2) - ox
            ul(6 * i - 1) = ul(6 * i - 1) - oy
        end do
    end subroutine remove_zero_energy_mode

    !> K_global = T^T K_local T with T = blockdiag(rot) over nb 3x3 blocks.
    !>  rot : in, rows = local axes; nb : in, number of 3-vectors (2 per node)
    !>  kl  : in, local matrix; kg : out, global matrix
    pure subroutine rotate_to_global(rot, nb, kl, kg)
        integer(i4), intent(in) :: nb
        real(dp), intent(in) :: rot(3, 3), kl(3 * nb, 3 * nb)
        real(dp), intent(out) :: kg(3 * nb, 3 * nb)
        integer(i4) :: a, b
        do b = 1, nb
            do a = 1, nb
                kg(3 * a - 2:3 * a, 3 * b - 2:3 * b) = matmul(transpose(rot), &
                    matmul(kl(3 * a - 2:3 * a, 3 * b - 2:3 * b), rot))
            end do
        end do
    end subroutine rotate_to_global

    !> Constant-strain triangle membrane: K = A B^T D B (D already times the thickness).
    subroutine membrane_tria3_stiffness(xy, dmat, km, st)
        real(dp), intent(in) :: xy(2, 3), dmat(3, 3)
        real(dp), intent(out) :: km(6, 6)
        type(status_t), intent(out) :: st
        real(dp) :: b(3, 6), area2, bi, ci
        integer(i4) :: i, j, k
        km = 0.0_dp
        area2 = (xy(1, 2) - xy(1, 1)) * (xy(2, 3) - xy(2, 1)) - &
                (xy(1, 3) - xy(1, 1)) * (xy(2, 2) - xy(2, 1))
        if (.not. area2 > 0.0_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'TRIA3 cell has zero area')
            return
        end if
        b = 0.0_dp
        do i = 1, 3
            j = mod(i, 3_i4) + 1
            k = mod(j, 3_i4) + 1
            bi = (xy(2, j) - xy(2, k)) / area2
            ci = (xy(1, k) - xy(1, j)) / area2
            b(1, 2 * i - 1) = bi
            b(2, 2 * i) = ci
            b(3, 2 * i - 1) = ci
            b(3, 2 * i) = bi
        end do
        km = matmul(transpose(b), matmul(dmat, b)) * (0.5_dp * area2)
    end subroutine membrane_tria3_stiffness

    pure function cross(a, b) result(c)
        real(dp), intent(in) :: a(3), b(3)
        real(dp) :: c(3)
        c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
    end function cross

end module element_plate
