!> What CALC_CHAMP computes at a point of a DKT/DKQ plate (element_plate's element), in its
!> local frame (plate_local_frame), and the turn to the frame the results are given in.
!>
!> At a reference point of the cell, from the local displacements (u, v, w, thx, thy, thz
!> per node):
!>  - membrane strains e = (u,x ; v,y ; u,y + v,x) of the bilinear Q4 / constant-strain
!>    triangle membrane;
!>  - curvatures k = (bx,x ; by,y ; bx,y + by,x) of the discrete Kirchhoff bending
!>    (element_kirchhoff_bending, bx = thy, by = -thx);
!>  - shear forces T = (Mxx,x + Mxy,y ; Mxy,x + Myy,y), M = Df k, from the second
!>    derivatives of the quadratic rotation field, turned from (xi, eta) to (x, y) with
!>    the inverse Jacobian at the point (its variation over the cell neglected: exact on
!>    parallelograms), as Code_Aster's DKT/DKQ shear (Batoz; Code_Aster dkqtxy, dkttxy,
!>    dsxhft). A Kirchhoff plate has no shear strain of its own: T is the equilibrium value.
!> Generalised forces N = Dm e (Dm = h E/(1-nu^2) (1 nu 0; nu 1 0; 0 0 (1-nu)/2)), M = Df k
!> (Df = h^3/12 E/(1-nu^2) (...)), T; stresses at height z: s = (Dm/h)(e + z k), the
!> transverse shear (6/h^3)(h^2/4 - z^2) T (parabolic, integrating to T).
!>
!> Results are given in the user's frame of the cell (AFFE_CARA_ELEM COQUE ANGL_REP /
!> VECTEUR; Code_Aster coqrep): x_user = the direction d projected on the cell's plane,
!> z_user the cell's normal. plate_user_turn gives (c, s), x_user = c x + s y in the local
!> frame; tensors turn as T^t A T, vectors as T^t v, T = (c -s; s c).
module element_plate_fields
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use element_kirchhoff_bending, only: kirchhoff_bending_b, kirchhoff_rotation_map, &
        MAP_ROWS, MAP_COLS
    implicit none
    private

    public :: plate_point_strains, plate_point_shear, plate_user_turn, turn_plate_tensor, &
        turn_plate_vector, plate_rigidities

contains

    !> Membrane and bending rigidities of an isotropic plate of thickness h.
    !>  dm : out, h E/(1-nu^2) (1 nu 0; nu 1 0; 0 0 (1-nu)/2)
    !>  df : out, h^2/12 dm;  dc : out, the shear rigidity 5/6 G h (Code_Aster dxmate)
    pure subroutine plate_rigidities(young, nu, thickness, dm, df, dc)
        real(dp), intent(in) :: young, nu, thickness
        real(dp), intent(out) :: dm(3, 3), df(3, 3), dc
        real(dp) :: c
        c = thickness * young / (1.0_dp - nu * nu)
        dm = 0.0_dp
        dm(1, 1) = c
        dm(1, 2) = c * nu
        dm(2, 1) = c * nu
        dm(2, 2) = c
        dm(3, 3) = c * (1.0_dp - nu) / 2.0_dp
        c = young * thickness**3 / 12.0_dp / (1.0_dp - nu * nu)
        df = 0.0_dp
        df(1, 1) = c
        df(1, 2) = c * nu
        df(2, 1) = c * nu
        df(2, 2) = c
        df(3, 3) = c * (1.0_dp - nu) / 2.0_dp
        dc = 5.0_dp / 6.0_dp * young / 2.0_dp / (1.0_dp + nu) * thickness
    end subroutine plate_rigidities

    !> Membrane strains and curvatures at reference point xi.
    !>  xy : in, local node coordinates; nn : in, 3 or 4
    !>  ul : in, (6 nn) local displacements (u, v, w, thx, thy, thz per node)
    !>  xi : in, (L2, L3) on the triangle, [-1, 1]^2 on the quadrilateral
    !>  e, k : out, (xx, yy, xy) engineering shear
    !>  det : out, the Jacobian determinant (<= 0: a degenerate cell, e = k = 0)
    !>  map_x, map_y : in, optional, the cell's rotation map (kirchhoff_rotation_map), for
    !>        a caller evaluating several points of a cell
    pure subroutine plate_point_strains(xy, nn, ul, xi, e, k, det, map_x, map_y)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: xy(2, nn), ul(6 * nn), xi(2)
        real(dp), intent(out) :: e(3), k(3), det
        real(dp), intent(in), optional :: map_x(MAP_ROWS, MAP_COLS), map_y(MAP_ROWS, MAP_COLS)
        real(dp) :: bb(3, MAP_ROWS), ub(MAP_ROWS), dxy(2, 4)
        integer(i4) :: i, m
        e = 0.0_dp
        k = 0.0_dp
        m = 3 * nn
        call kirchhoff_bending_b(xy, nn, xi, bb, det, map_x, map_y)   ! bb(:, 1:3nn)
        if (.not. det > 0.0_dp) return
        do i = 1, nn
            ub(3 * i - 2:3 * i) = ul(6 * i - 3:6 * i - 1)
        end do
        k = matmul(bb(:, 1:m), ub(1:m))
        call linear_derivatives(xy, nn, xi, dxy)
        do i = 1, nn
            e(1) = e(1) + dxy(1, i) * ul(6 * i - 5)
            e(2) = e(2) + dxy(2, i) * ul(6 * i - 4)
            e(3) = e(3) + dxy(2, i) * ul(6 * i - 5) + dxy(1, i) * ul(6 * i - 4)
        end do
    end subroutine plate_point_strains

    !> x, y derivatives of the linear (TRIA3) / bilinear (QUAD4) shape functions at xi.
    pure subroutine linear_derivatives(xy, nn, xi, dxy)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: xy(2, nn), xi(2)
        real(dp), intent(out) :: dxy(2, 4)
        real(dp) :: dg(2, 4), jac(2, 2), det
        real(dp), parameter :: xc(4) = [-1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp]
        real(dp), parameter :: yc(4) = [-1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp]
        integer(i4) :: i
        dg = 0.0_dp
        dxy = 0.0_dp
        if (nn == 3) then
            dg(:, 1) = [-1.0_dp, -1.0_dp]
            dg(:, 2) = [1.0_dp, 0.0_dp]
            dg(:, 3) = [0.0_dp, 1.0_dp]
        else
            do i = 1, 4
                dg(1, i) = 0.25_dp * xc(i) * (1.0_dp + yc(i) * xi(2))
                dg(2, i) = 0.25_dp * yc(i) * (1.0_dp + xc(i) * xi(1))
            end do
        end if
        jac = matmul(dg(:, 1:nn), transpose(xy))
        det = jac(1, 1) * jac(2, 2) - jac(1, 2) * jac(2, 1)
        if (.not. det > 0.0_dp) return
        dxy(1, 1:nn) = (jac(2, 2) * dg(1, 1:nn) - jac(1, 2) * dg(2, 1:nn)) / det
        dxy(2, 1:nn) = (-jac(2, 1) * dg(1, 1:nn) + jac(1, 1) * dg(2, 1:nn)) / det
    end subroutine linear_derivatives

    !> Shear forces T = (Qx, Qy) at reference point xi (module header).
    !>  df : in, the bending rigidity;  other arguments as plate_point_strains
    pure subroutine plate_point_shear(xy, nn, ul, df, xi, t, dk_out, map_x, map_y)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: xy(2, nn), ul(6 * nn), df(3, 3), xi(2)
        real(dp), intent(out) :: t(2)
        !> the curvatures' gradient (d/dx, d/dy of k1 k2 k3), laminates' shear stresses (elem)
        real(dp), intent(out), optional :: dk_out(3, 2)
        !> the cell's rotation map, as plate_point_strains
        real(dp), intent(in), optional :: map_x(MAP_ROWS, MAP_COLS), map_y(MAP_ROWS, MAP_COLS)
        real(dp) :: bx(MAP_ROWS, MAP_COLS), by(MAP_ROWS, MAP_COLS), ub(MAP_ROWS)
        real(dp) :: d2(3, 8), dg(2, 4), jac(2, 2), inv(2, 2), det
        real(dp) :: bxv(8), byv(8), hx(3), hy(3), w(3, 3), dk(3, 2), h2(3)
        real(dp), parameter :: xc(4) = [-1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp]
        real(dp), parameter :: yc(4) = [-1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp]
        integer(i4) :: i, nr, m
        t = 0.0_dp
        if (present(dk_out)) dk_out = 0.0_dp
        nr = 2 * nn
        m = 3 * nn
        do i = 1, nn
            ub(3 * i - 2:3 * i) = ul(6 * i - 3:6 * i - 1)
        end do
        if (present(map_x) .and. present(map_y)) then
            bxv(1:nr) = matmul(ub(1:m), map_x(1:m, 1:nr))  ! beta_x, beta_y at the 2nn nodes
            byv(1:nr) = matmul(ub(1:m), map_y(1:m, 1:nr))
        else
            call kirchhoff_rotation_map(xy, nn, bx, by)
            bxv(1:nr) = matmul(ub(1:m), bx(1:m, 1:nr))
            byv(1:nr) = matmul(ub(1:m), by(1:m, 1:nr))
        end if
        call quadratic_second_derivatives(nn, xi, d2)
        dg = 0.0_dp
        if (nn == 3) then
            dg(:, 1) = [-1.0_dp, -1.0_dp]
            dg(:, 2) = [1.0_dp, 0.0_dp]
            dg(:, 3) = [0.0_dp, 1.0_dp]
        else
            do i = 1, 4
                dg(1, i) = 0.25_dp * xc(i) * (1.0_dp + yc(i) * xi(2))
                dg(2, i) = 0.25_dp * yc(i) * (1.0_dp + xc(i) * xi(1))
            end do
        end if
        jac = matmul(dg(:, 1:nn), transpose(xy))
        det = jac(1, 1) * jac(2, 2) - jac(1, 2) * jac(2, 1)
        if (.not. det > 0.0_dp) return
        inv(1, :) = [jac(2, 2), -jac(1, 2)] / det     ! (d/dx, d/dy) = inv (d/dxi, d/deta)
        inv(2, :) = [-jac(2, 1), jac(1, 1)] / det
        ! second derivatives (xx, yy, xy) from (xi xi, eta eta, xi eta), constant inverse
        ! Jacobian (Code_Aster's T2 of dsxhft)
        w(1, :) = [inv(1, 1)**2, inv(1, 2)**2, 2.0_dp * inv(1, 1) * inv(1, 2)]
        w(2, :) = [inv(2, 1)**2, inv(2, 2)**2, 2.0_dp * inv(2, 1) * inv(2, 2)]
        w(3, :) = [inv(1, 1) * inv(2, 1), inv(1, 2) * inv(2, 2), &
                   inv(1, 1) * inv(2, 2) + inv(1, 2) * inv(2, 1)]
        ! (the inner products into h2: a temporary of the nested matmul is allocated)
        h2 = matmul(d2(:, 1:nr), bxv(1:nr))
        hx = matmul(w, h2)                                 ! beta_x,xx ,yy ,xy
        h2 = matmul(d2(:, 1:nr), byv(1:nr))
        hy = matmul(w, h2)                                 ! beta_y,xx ,yy ,xy
        ! curvature derivatives: dk(:, 1) = d/dx (k1, k2, k3), dk(:, 2) = d/dy
        dk(:, 1) = [hx(1), hy(3), hx(3) + hy(1)]
        dk(:, 2) = [hx(3), hy(2), hx(2) + hy(3)]
        t(1) = dot_product(df(1, :), dk(:, 1)) + dot_product(df(3, :), dk(:, 2))
        t(2) = dot_product(df(3, :), dk(:, 1)) + dot_product(df(2, :), dk(:, 2))
        if (present(dk_out)) dk_out = dk
    end subroutine plate_point_shear

    !> Second derivatives (xi xi, eta eta, xi eta) of the quadratic rotation shape functions
    !> (6-node triangle in (L2, L3); 8-node serendipity quadrilateral), in the node order of
    !> element_kirchhoff_bending: corners, then the middles of sides 1-2, 2-3, ...
    pure subroutine quadratic_second_derivatives(nn, xi, d2)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: xi(2)
        real(dp), intent(out) :: d2(3, 8)
        real(dp), parameter :: xc(4) = [-1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp]
        real(dp), parameter :: yc(4) = [-1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp]
        real(dp) :: dl(2, 3), x, y
        integer(i4) :: i, j
        d2 = 0.0_dp
        if (nn == 3) then
            dl(:, 1) = [-1.0_dp, -1.0_dp]
            dl(:, 2) = [1.0_dp, 0.0_dp]
            dl(:, 3) = [0.0_dp, 1.0_dp]
            do i = 1, 3
                j = mod(i, 3_i4) + 1
                ! L_i (2 L_i - 1): 4 dL_i dL_i; 4 L_i L_j: 4 (dL_i dL_j + dL_j dL_i)
                d2(:, i) = 4.0_dp * [dl(1, i)**2, dl(2, i)**2, dl(1, i) * dl(2, i)]
                d2(:, 3 + i) = 4.0_dp * [2.0_dp * dl(1, i) * dl(1, j), &
                    2.0_dp * dl(2, i) * dl(2, j), dl(1, i) * dl(2, j) + dl(1, j) * dl(2, i)]
            end do
            return
        end if
        x = xi(1)
        y = xi(2)
        do i = 1, 4
            d2(1, i) = 0.5_dp * (1.0_dp + yc(i) * y)
            d2(2, i) = 0.5_dp * (1.0_dp + xc(i) * x)
            d2(3, i) = 0.25_dp * xc(i) * yc(i) * (2.0_dp * xc(i) * x + 2.0_dp * yc(i) * y + &
                1.0_dp)
        end do
        d2(:, 5) = [-(1.0_dp - y), 0.0_dp, x]            ! side 1-2 (eta = -1)
        d2(:, 6) = [0.0_dp, -(1.0_dp + x), -y]           ! side 2-3 (xi = +1)
        d2(:, 7) = [-(1.0_dp + y), 0.0_dp, -x]           ! side 3-4 (eta = +1)
        d2(:, 8) = [0.0_dp, -(1.0_dp - x), y]            ! side 4-1 (xi = -1)
    end subroutine quadratic_second_derivatives

    !> The turn from a cell's local frame to its user frame (module header): x_user is the
    !> direction d projected on the plane of normal rot(3, :).
    !>  rot       : in, rows = local x, y, normal (plate_local_frame)
    !>  direction : in, d (ANGL_REP / VECTEUR; global X by default)
    !>  c, s      : out, x_user = c x_local + s y_local
    !>  st        : STATUS_MODEL_ERROR when d is normal to the cell (no projection)
    subroutine plate_user_turn(rot, direction, c, s, st)
        real(dp), intent(in) :: rot(3, 3), direction(3)
        real(dp), intent(out) :: c, s
        type(status_t), intent(out) :: st
        real(dp) :: d(3), p(3), length
        c = 1.0_dp
        s = 0.0_dp
        length = norm2(direction)
        if (.not. length > 0.0_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'the direction of the plate''s frame ' // &
                '(ANGL_REP, VECTEUR) is zero')
            return
        end if
        d = direction / length
        p = d - dot_product(d, rot(3, :)) * rot(3, :)
        length = norm2(p)
        if (.not. length > 1.0e3_dp * epsilon(1.0_dp)) then
            call set_error(st, STATUS_MODEL_ERROR, 'the direction of the plate''s frame ' // &
                '(ANGL_REP, VECTEUR) is normal to the cell: give another one')
            return
        end if
        p = p / length
        c = dot_product(p, rot(1, :))
        s = dot_product(p, rot(2, :))
        length = hypot(c, s)
        c = c / length
        s = s / length
    end subroutine plate_user_turn

    !> A symmetric 2D tensor (xx, yy, xy) from the local to the user frame: T^t A T.
    pure function turn_plate_tensor(c, s, a) result(b)
        real(dp), intent(in) :: c, s, a(3)
        real(dp) :: b(3)
        b(1) = c * c * a(1) + s * s * a(2) + 2.0_dp * c * s * a(3)
        b(2) = s * s * a(1) + c * c * a(2) - 2.0_dp * c * s * a(3)
        b(3) = c * s * (a(2) - a(1)) + (c * c - s * s) * a(3)
    end function turn_plate_tensor

    !> An in-plane vector (x, y) from the local to the user frame: T^t v.
    pure function turn_plate_vector(c, s, v) result(w)
        real(dp), intent(in) :: c, s, v(2)
        real(dp) :: w(2)
        w(1) = c * v(1) + s * v(2)
        w(2) = -s * v(1) + c * v(2)
    end function turn_plate_vector

end module element_plate_fields
