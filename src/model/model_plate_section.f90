!> The section of a DKT/DKQ plate cell: its membrane, coupling and bending rigidities
!> (N = Dm e + Dmf k, M = Dmf e + Df k; e the membrane strains, k the curvatures of the
!> reference surface, engineering shear) and its transverse shear rigidity Dc, as Code_Aster's
!> dxmate builds them (R3.07.03), from the cell's material and COQUE characteristics:
!>  - ELAS (isotropic, E and NU; ELAS_FO's at the cell's mean temperature): Dm = h Q,
!>    Df = h^3/12 Q, Q the plane-stress matrix, Dc = 5/6 G h;
!>  - ELAS_COQUE / ELAS_COQUE_FO: the rigidities given, MEMB_L ... CISA_T (no coupling) or
!>    M_LLLL ... C_TZTZ (with the coupling MF_*), in the frame of ANGL_REP / VECTEUR (L its
!>    x axis, T its y axis);
!>  - a DEFI_COMPOSITE laminate (behaviour ELAS_COQMU, composite_command): each layer's
!>    reduced stiffness Q (E_L, E_T, NU_LT, G_LT of its ELAS_ORTH) turned by its ORIENTATION
!>    (degrees, from L towards T) into the frame of ANGL_REP, integrated through the stack
!>    from its bottom face at -H/2 (H the layers' total): Dm = sum Q e_i, Dmf = sum Q e_i z_i,
!>    Df = sum Q e_i (z_i^2 + e_i^2/12); Dc from the layers' transverse shear moduli G_LN,
!>    G_TN as Code_Aster's op0056 (the energy of the equilibrium shear stresses).
!> EXCENTREMENT e moves the reference surface (the mesh) below the mid surface: Df += 2 e Dmf
!> + e^2 Dm, then Dmf += e Dm. ELAS_COQUE and laminates are given in the user frame (the
!> `oriented` section): section_in_element turns them to the element's axes, T^t D T with
!> Code_Aster's T (coqrep, t1ve); ELAS is the same in every frame.
!> ELAS_ORTH straight on a plate is refused as Code_Aster refuses it (ELEMENTS_91: a
!> laminate goes through DEFI_COMPOSITE); a laminate whose layer count is not COQUE_NCOU, or
!> whose total thickness is more than 1 % off EPAIS, is refused (PLATE1_2, PLATE1_3).
module model_plate_section
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: to_text, real_e13
    use function_concept, only: function_concept_t, param_binding_t
    use model_material, only: material_t, has_behaviour, behaviour_number, &
        behaviour_function, behaviour_index, VALUE_NUMBERS
    use model_cara_elem, only: cara_elem_t
    implicit none
    private

    !> Code_Aster's shear correction of homogeneous plates (dxmate kcis).
    real(dp), parameter :: SHEAR_CORRECTION = 5.0_dp / 6.0_dp

    !> The section of one plate cell (module header).
    type, public :: plate_section_t
        real(dp) :: thickness = 0.0_dp      !< COQUE/EPAIS
        real(dp) :: offset = 0.0_dp         !< COQUE/EXCENTREMENT
        integer(i4) :: layers = 1           !< COQUE_NCOU (the laminate's layers)
        logical :: isotropic = .true.       !< ELAS: the same in every frame
        logical :: laminate = .false.       !< DEFI_COMPOSITE
        logical :: coupled = .false.        !< Dmf /= 0
        real(dp) :: young = 0.0_dp, nu = 0.0_dp    !< ELAS
        real(dp) :: dm(3, 3) = 0.0_dp, dmf(3, 3) = 0.0_dp, df(3, 3) = 0.0_dp
        real(dp) :: dc(2, 2) = 0.0_dp       !< transverse shear rigidity
        !> the laminate's layers: their faces z (layers + 1, from the reference surface:
        !> offset included) and reduced stiffnesses q (3, 3, layers), in the section's frame
        real(dp), allocatable :: z(:), q(:, :, :)
        !> the laminate's bending rigidity about the middle of its stack (its shear stresses)
        real(dp) :: hf(3, 3) = 0.0_dp
    end type plate_section_t

    public :: plate_section, section_in_element, section_turn_matrix, plate_section_material, &
        elas_fo_isotropic

contains

    !> True when `mat` gives a plate section parasol builds (ELAS, ELAS_FO, ELAS_COQUE,
    !> ELAS_COQUE_FO, a DEFI_COMPOSITE laminate).
    logical function plate_section_material(mat)
        type(material_t), intent(in) :: mat
        plate_section_material = mat%has_elas .or. has_behaviour(mat, 'ELAS_FO') .or. &
            has_behaviour(mat, 'ELAS_COQUE') .or. has_behaviour(mat, 'ELAS_COQUE_FO') .or. &
            has_behaviour(mat, 'ELAS_COQMU')
    end function plate_section_material

    !> The section of plate cell c (module header), in its user frame.
    !>  temp : in, optional, the cell's mean temperature (the functions of ELAS_FO and
    !>         ELAS_COQUE_FO are evaluated there; without it they must not need TEMP)
    !>  st   : STATUS_MODEL_ERROR (no thickness, ELAS_ORTH straight, a laminate that does not
    !>         fit COQUE, a rigidity function failing), STATUS_NOT_IMPLEMENTED (another
    !>         elastic behaviour); the caller names the cell
    subroutine plate_section(mat, cara, c, sec, st, temp)
        type(material_t), intent(in) :: mat
        type(cara_elem_t), intent(in) :: cara
        integer(i4), intent(in) :: c
        type(plate_section_t), intent(out) :: sec
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: temp
        real(dp) :: e
        integer(i4) :: i, j
        sec%thickness = cara%thickness(c)
        sec%offset = 0.0_dp
        if (allocated(cara%coque_offset)) sec%offset = cara%coque_offset(c)
        sec%layers = max(1_i4, cara%coque_layers(c))
        if (.not. sec%thickness > 0.0_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'the plate has no thickness: give it ' // &
                'AFFE_CARA_ELEM COQUE EPAIS (CARA_ELEM)')
            return
        end if
        if (has_behaviour(mat, 'ELAS_COQMU')) then
            call laminate_section(mat, sec, st)
        else if (has_behaviour(mat, 'ELAS_COQUE') .or. has_behaviour(mat, 'ELAS_COQUE_FO')) then
            call given_section(mat, sec, st, temp)
        else if (mat%has_elas .or. has_behaviour(mat, 'ELAS_FO')) then
            call isotropic_section(mat, sec, st, temp)
        else if (has_behaviour(mat, 'ELAS_ORTH')) then
            call set_error(st, STATUS_MODEL_ERROR, 'ELAS_ORTH on a DKT plate: Code_Aster ' // &
                'refuses it (ELEMENTS_91); give the layers through DEFI_COMPOSITE')
            return
        else
            call set_error(st, STATUS_MODEL_ERROR, 'the plate''s material has no ' // &
                'elasticity (ELAS, ELAS_COQUE or a DEFI_COMPOSITE laminate)')
            return
        end if
        if (st%failed()) return
        e = sec%offset
        if (abs(e) > 0.0_dp) then
            sec%df = sec%df + 2.0_dp * e * sec%dmf + e * e * sec%dm
            sec%dmf = sec%dmf + e * sec%dm
            if (allocated(sec%z)) sec%z = sec%z + e
        end if
        sec%coupled = .false.
        do j = 1, 3
            do i = 1, 3
                if (abs(sec%dmf(i, j)) > 1.0e-10_dp) sec%coupled = .true.     ! dxmate's test
            end do
        end do
    end subroutine plate_section

    !> E and NU of the material's ELAS_FO, its functions evaluated at temperature `temp`
    !> (without it, functions of no parameter: DEFI_CONSTANTE; a function of TEMP then is
    !> an error naming it). Shared by the plates and the plane elements.
    !>  st : out, STATUS_MODEL_ERROR for a function failing, E <= 0 or NU outside (-1, 0.5)
    subroutine elas_fo_isotropic(mat, young, nu, st, temp)
        type(material_t), intent(in) :: mat
        real(dp), intent(out) :: young, nu
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: temp
        nu = 0.0_dp
        call material_value(mat, 'ELAS_FO', 'E', young, st, temp)
        if (st%ok()) call material_value(mat, 'ELAS_FO', 'NU', nu, st, temp)
        if (st%failed()) return
        if (.not. young > 0.0_dp .or. nu <= -1.0_dp .or. nu >= 0.5_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'ELAS_FO gives E = ' // &
                real_e13(young) // ', NU = ' // real_e13(nu) // ': E > 0 and ' // &
                '-1 < NU < 0.5 are needed')
        end if
    end subroutine elas_fo_isotropic

    ! ELAS (E, NU; ELAS_FO's at temp): dxmate's isotropic rigidities. The layers of
    ! COQUE_NCOU split the thickness evenly (their sub-points for the stresses).
    subroutine isotropic_section(mat, sec, st, temp)
        type(material_t), intent(in) :: mat
        type(plate_section_t), intent(inout) :: sec
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: temp
        real(dp) :: young, nu, q(3, 3), h
        integer(i4) :: k
        if (mat%has_elas) then
            young = mat%elas%e
            nu = mat%elas%nu
        else
            call elas_fo_isotropic(mat, young, nu, st, temp)
            if (st%failed()) return
        end if
        sec%young = young
        sec%nu = nu
        h = sec%thickness
        q = plane_stress(young, nu)
        sec%dm = h * q
        sec%df = (h**3 / 12.0_dp) * q
        sec%dmf = 0.0_dp
        sec%dc = 0.0_dp
        sec%dc(1, 1) = young / 2.0_dp / (1.0_dp + nu) * SHEAR_CORRECTION * h
        sec%dc(2, 2) = sec%dc(1, 1)
        allocate (sec%z(sec%layers + 1), sec%q(3, 3, sec%layers))
        do k = 0, sec%layers
            sec%z(k + 1) = -h / 2.0_dp + real(k, dp) * h / real(sec%layers, dp)
        end do
        do k = 1, sec%layers
            sec%q(:, :, k) = q
        end do
    end subroutine isotropic_section

    ! ELAS_COQUE (numbers) or ELAS_COQUE_FO (functions, at temp): dxmate's two forms.
    subroutine given_section(mat, sec, st, temp)
        type(material_t), intent(in) :: mat
        type(plate_section_t), intent(inout) :: sec
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: temp
        character(len=*), parameter :: SHORT(10) = [character(len=9) :: 'MEMB_L', 'MEMB_LT', &
            'MEMB_T', 'MEMB_G_LT', 'FLEX_L', 'FLEX_LT', 'FLEX_T', 'FLEX_G_LT', 'CISA_L', &
            'CISA_T']
        character(len=*), parameter :: FULL(21) = [character(len=7) :: 'M_LLLL', 'M_LLTT', &
            'M_LLLT', 'M_TTTT', 'M_TTLT', 'M_LTLT', 'F_LLLL', 'F_LLTT', 'F_LLLT', 'F_TTTT', &
            'F_TTLT', 'F_LTLT', 'MF_LLLL', 'MF_LLTT', 'MF_LLLT', 'MF_TTTT', 'MF_TTLT', &
            'MF_LTLT', 'C_LZLZ', 'C_LZTZ', 'C_TZTZ']
        character(len=:), allocatable :: b
        real(dp) :: v(21)
        integer(i4) :: k
        b = 'ELAS_COQUE'
        if (.not. has_behaviour(mat, b)) b = 'ELAS_COQUE_FO'
        sec%isotropic = .false.
        sec%dm = 0.0_dp
        sec%dmf = 0.0_dp
        sec%df = 0.0_dp
        sec%dc = 0.0_dp
        if (given(mat, b, 'MEMB_L')) then
            do k = 1, size(SHORT)
                call material_value(mat, b, trim(SHORT(k)), v(k), st, temp)
                if (st%failed()) return
            end do
            sec%dm(1, 1:2) = [v(1), v(2)]
            sec%dm(2, 1:2) = [v(2), v(3)]
            sec%dm(3, 3) = v(4)
            sec%df(1, 1:2) = [v(5), v(6)]
            sec%df(2, 1:2) = [v(6), v(7)]
            sec%df(3, 3) = v(8)
            sec%dc(1, 1) = v(9)
            sec%dc(2, 2) = v(10)
        else
            do k = 1, size(FULL)
                call material_value(mat, b, trim(FULL(k)), v(k), st, temp)
                if (st%failed()) return
            end do
            sec%dm = symmetric(v(1:6))
            sec%df = symmetric(v(7:12))
            sec%dmf = symmetric(v(13:18))
            sec%dc(1, :) = [v(19), v(20)]
            sec%dc(2, :) = [v(20), v(21)]
        end if
    end subroutine given_section

    ! A DEFI_COMPOSITE laminate (module header; Code_Aster's op0056 and dxmate).
    subroutine laminate_section(mat, sec, st)
        type(material_t), intent(in) :: mat
        type(plate_section_t), intent(inout) :: sec
        type(status_t), intent(out) :: st
        real(dp), allocatable :: epais(:), orient(:), el(:), et(:), nult(:), glt(:), gln(:), &
            gtn(:)
        real(dp) :: total, zb, ordi, epi, hfinv(3, 3), qi(3, 3), gi(2, 2)
        real(dp) :: ai(3, 3), da1(2, 2), idi(2, 2), ezd(2, 2), hti(2, 2), htinv(2, 2)
        real(dp) :: x1, x2, x4, c11i(2, 2), c11(2, 2), det
        integer(i4) :: n, k
        logical :: ok
        call layer_numbers(mat, 'EPAIS', epais, ok)
        if (ok) call layer_numbers(mat, 'ORIENTATION', orient, ok)
        if (ok) call layer_numbers(mat, 'E_L', el, ok)
        if (ok) call layer_numbers(mat, 'E_T', et, ok)
        if (ok) call layer_numbers(mat, 'NU_LT', nult, ok)
        if (ok) call layer_numbers(mat, 'G_LT', glt, ok)
        if (ok) call layer_numbers(mat, 'G_LN', gln, ok)
        if (ok) call layer_numbers(mat, 'G_TN', gtn, ok)
        if (.not. ok) then
            call set_error(st, STATUS_MODEL_ERROR, 'the laminate''s layers are incomplete')
            return
        end if
        n = size(epais, kind=i4)
        total = sum(epais)
        if (n /= sec%layers) then
            call set_error(st, STATUS_MODEL_ERROR, 'DEFI_COMPOSITE gives ' // to_text(n) // &
                ' layer(s), AFFE_CARA_ELEM COQUE_NCOU ' // to_text(sec%layers) // &
                ': they must agree (Code_Aster PLATE1_2)')
            return
        end if
        if (abs(sec%thickness - total) / sec%thickness > 1.0e-2_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'the layers of DEFI_COMPOSITE are ' // &
                real_e13(total) // ' thick, AFFE_CARA_ELEM EPAIS ' // &
                real_e13(sec%thickness) // ': they must agree within 1 % (Code_Aster PLATE1_3)')
            return
        end if
        sec%isotropic = .false.
        sec%laminate = .true.
        allocate (sec%z(n + 1), sec%q(3, 3, n))
        sec%dm = 0.0_dp
        sec%dmf = 0.0_dp
        sec%df = 0.0_dp
        zb = -0.5_dp * total
        sec%z(1) = zb
        do k = 1, n
            epi = epais(k)
            ordi = zb + 0.5_dp * epi
            zb = zb + epi
            sec%z(k + 1) = zb
            sec%q(:, :, k) = layer_stiffness(el(k), et(k), nult(k), glt(k), orient(k))
            sec%dm = sec%dm + sec%q(:, :, k) * epi
            sec%dmf = sec%dmf + sec%q(:, :, k) * epi * ordi
            sec%df = sec%df + sec%q(:, :, k) * epi * (ordi**2 + epi**2 / 12.0_dp)
        end do
        sec%hf = sec%df
        ! the transverse shear rigidity (op0056: c11 and its inverse)
        call invert3(sec%hf, hfinv, ok)
        if (.not. ok) then
            call set_error(st, STATUS_MODEL_ERROR, 'the laminate has no bending rigidity')
            return
        end if
        ezd = 0.0_dp
        c11 = 0.0_dp
        do k = 1, n
            epi = epais(k)
            ordi = 0.5_dp * (sec%z(k) + sec%z(k + 1))
            qi = sec%q(:, :, k)
            ai = matmul(qi, hfinv)
            da1(1, :) = [ai(1, 1) + ai(3, 3), ai(1, 3) + ai(3, 2)]
            da1(2, :) = [ai(3, 1) + ai(2, 3), ai(2, 2) + ai(3, 3)]
            idi = ezd - ((ordi - epi / 2.0_dp)**2) * da1 / 2.0_dp
            ezd = ezd + epi * ordi * da1
            gi = layer_shear(gln(k), gtn(k), orient(k))
            hti = gi
            det = hti(1, 1) * hti(2, 2) - hti(1, 2) * hti(2, 1)
            htinv = 0.0_dp
            if (abs(det) >= tiny(1.0_dp)) then
                htinv(1, :) = [hti(2, 2), -hti(1, 2)] / det
                htinv(2, :) = [-hti(2, 1), hti(1, 1)] / det
            end if
            x1 = epi / 4.0_dp
            x2 = (3.0_dp * ordi * ordi * epi + epi**3 / 4.0_dp) / 24.0_dp
            x4 = (5.0_dp * ordi**4 * epi + 2.5_dp * ordi * ordi * epi**3 + epi**5 / 16.0_dp) &
                / 80.0_dp
            c11i = x1 * matmul(transpose(idi), matmul(htinv, idi)) + &
                x2 * matmul(transpose(idi), matmul(htinv, da1)) + &
                x2 * matmul(transpose(da1), matmul(htinv, idi)) + &
                x4 * matmul(transpose(da1), matmul(htinv, da1))
            c11 = c11 + c11i
        end do
        det = c11(1, 1) * c11(2, 2) - c11(1, 2) * c11(2, 1)
        sec%dc = 0.0_dp
        if (abs(det) >= tiny(1.0_dp)) then
            sec%dc(1, :) = [c11(2, 2), -c11(1, 2)] / det
            sec%dc(2, :) = [-c11(2, 1), c11(1, 1)] / det
        end if
    end subroutine laminate_section

    !> The section turned to the element's axes (module header): c, s the user frame's x
    !> axis in the element's (plate_user_turn: x_user = c x + s y).
    pure subroutine section_in_element(sec, c, s, turned)
        type(plate_section_t), intent(in) :: sec
        real(dp), intent(in) :: c, s
        type(plate_section_t), intent(out) :: turned
        real(dp) :: t(3, 3), t2(2, 2)
        integer(i4) :: k
        turned = sec
        if (sec%isotropic) return
        t = section_turn_matrix(c, s)
        turned%dm = matmul(transpose(t), matmul(sec%dm, t))
        turned%dmf = matmul(transpose(t), matmul(sec%dmf, t))
        turned%df = matmul(transpose(t), matmul(sec%df, t))
        turned%hf = matmul(transpose(t), matmul(sec%hf, t))
        t2(1, :) = [c, s]                  ! Code_Aster's t2ui
        t2(2, :) = [-s, c]
        turned%dc = matmul(transpose(t2), matmul(sec%dc, t2))
        if (allocated(sec%q)) then
            do k = 1, size(sec%q, 3)
                turned%q(:, :, k) = matmul(transpose(t), matmul(sec%q(:, :, k), t))
            end do
        end if
    end subroutine section_in_element

    !> Code_Aster's t1ve: the user-frame strains (engineering shear) of element-frame ones,
    !> e_user = T e_element, for x_user = c x + s y.
    pure function section_turn_matrix(c, s) result(t)
        real(dp), intent(in) :: c, s
        real(dp) :: t(3, 3)
        t(1, :) = [c * c, s * s, c * s]
        t(2, :) = [s * s, c * c, -c * s]
        t(3, :) = [-2.0_dp * c * s, 2.0_dp * c * s, c * c - s * s]
    end function section_turn_matrix

    ! The plane-stress matrix of E, NU.
    pure function plane_stress(young, nu) result(q)
        real(dp), intent(in) :: young, nu
        real(dp) :: q(3, 3), f
        f = young / (1.0_dp - nu * nu)
        q = 0.0_dp
        q(1, 1:2) = [f, f * nu]
        q(2, 1:2) = [f * nu, f]
        q(3, 3) = f * (1.0_dp - nu) / 2.0_dp
    end function plane_stress

    ! A layer's reduced stiffness turned by `orient` degrees (op0056 q11 ... q33).
    pure function layer_stiffness(el, et, nult, glt, orient) result(q)
        real(dp), intent(in) :: el, et, nult, glt, orient
        real(dp) :: q(3, 3), qll, qtt, qlt, c, s, c2, s2
        if (el < tiny(1.0_dp)) then
            qll = 0.0_dp
            qtt = et
        else
            qll = el / (1.0_dp - nult * nult * et / el)
            qtt = qll * et / el
        end if
        qlt = qtt * nult
        c = cos(orient * acos(-1.0_dp) / 180.0_dp)
        s = sin(orient * acos(-1.0_dp) / 180.0_dp)
        c2 = c * c
        s2 = s * s
        q(1, 1) = c2 * c2 * qll + s2 * s2 * qtt + 2.0_dp * c2 * s2 * qlt + 4.0_dp * c2 * s2 * glt
        q(2, 2) = s2 * s2 * qll + c2 * c2 * qtt + 2.0_dp * c2 * s2 * qlt + 4.0_dp * c2 * s2 * glt
        q(1, 2) = c2 * s2 * (qll + qtt - 4.0_dp * glt) + (s2 * s2 + c2 * c2) * qlt
        q(1, 3) = c2 * c * s * qll - c * s2 * s * qtt + (c * s2 * s - c2 * c * s) * &
            (qlt + 2.0_dp * glt)
        q(2, 3) = c * s2 * s * qll - c2 * c * s * qtt - (c * s2 * s - c2 * c * s) * &
            (qlt + 2.0_dp * glt)
        q(3, 3) = c2 * s2 * (qll + qtt - 2.0_dp * qlt) + (c2 - s2) * (c2 - s2) * glt
        q(2, 1) = q(1, 2)
        q(3, 1) = q(1, 3)
        q(3, 2) = q(2, 3)
    end function layer_stiffness

    ! A layer's transverse shear moduli turned by `orient` degrees (op0056 g11, g22, g12).
    pure function layer_shear(gln, gtn, orient) result(g)
        real(dp), intent(in) :: gln, gtn, orient
        real(dp) :: g(2, 2), c, s
        c = cos(orient * acos(-1.0_dp) / 180.0_dp)
        s = sin(orient * acos(-1.0_dp) / 180.0_dp)
        g(1, 1) = c * c * gln + s * s * gtn
        g(2, 2) = s * s * gln + c * c * gtn
        g(1, 2) = c * s * (gln - gtn)
        g(2, 1) = g(1, 2)
    end function layer_shear

    ! The symmetric 3x3 matrix of (11, 12, 13, 22, 23, 33).
    pure function symmetric(v) result(m)
        real(dp), intent(in) :: v(6)
        real(dp) :: m(3, 3)
        m(1, :) = [v(1), v(2), v(3)]
        m(2, :) = [v(2), v(4), v(5)]
        m(3, :) = [v(3), v(5), v(6)]
    end function symmetric

    pure subroutine invert3(a, inv, ok)
        real(dp), intent(in) :: a(3, 3)
        real(dp), intent(out) :: inv(3, 3)
        logical, intent(out) :: ok
        real(dp) :: det
        inv(1, 1) = a(2, 2) * a(3, 3) - a(2, 3) * a(3, 2)
        inv(1, 2) = a(1, 3) * a(3, 2) - a(1, 2) * a(3, 3)
        inv(1, 3) = a(1, 2) * a(2, 3) - a(1, 3) * a(2, 2)
        inv(2, 1) = a(2, 3) * a(3, 1) - a(2, 1) * a(3, 3)
        inv(2, 2) = a(1, 1) * a(3, 3) - a(1, 3) * a(3, 1)
        inv(2, 3) = a(1, 3) * a(2, 1) - a(1, 1) * a(2, 3)
        inv(3, 1) = a(2, 1) * a(3, 2) - a(2, 2) * a(3, 1)
        inv(3, 2) = a(1, 2) * a(3, 1) - a(1, 1) * a(3, 2)
        inv(3, 3) = a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)
        det = a(1, 1) * inv(1, 1) + a(1, 2) * inv(2, 1) + a(1, 3) * inv(3, 1)
        ok = abs(det) > 0.0_dp
        if (ok) inv = inv / det
    end subroutine invert3

    ! True when behaviour b gives keyword key (a number or a function).
    logical function given(mat, b, key)
        type(material_t), intent(in) :: mat
        character(len=*), intent(in) :: b, key
        real(dp) :: x
        call behaviour_number(mat, b, key, x, given)
        if (.not. given) given = associated(behaviour_function(mat, b, key))
    end function given

    ! The per-layer numbers of the laminate's keyword `key`.
    subroutine layer_numbers(mat, key, values, ok)
        type(material_t), intent(in) :: mat
        character(len=*), intent(in) :: key
        real(dp), allocatable, intent(out) :: values(:)
        logical, intent(out) :: ok
        integer :: b, k
        ok = .false.
        b = behaviour_index(mat, 'ELAS_COQMU')
        if (b == 0) return
        do k = 1, size(mat%behaviours(b)%values)
            associate (v => mat%behaviours(b)%values(k))
                if (v%key /= key .or. v%kind /= VALUE_NUMBERS) cycle
                values = v%numbers
                ok = .true.
                return
            end associate
        end do
    end subroutine layer_numbers

    ! The value of keyword `key` of behaviour b: its number, or its function at TEMP = temp.
    subroutine material_value(mat, b, key, x, st, temp)
        type(material_t), intent(in) :: mat
        character(len=*), intent(in) :: b, key
        real(dp), intent(out) :: x
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: temp
        class(function_concept_t), pointer :: f
        type(param_binding_t) :: binding
        logical :: found
        call behaviour_number(mat, b, key, x, found)
        if (found) return
        f => behaviour_function(mat, b, key)
        if (.not. associated(f)) then
            call set_error(st, STATUS_MODEL_ERROR, b // ' has no ' // key)
            return
        end if
        if (present(temp)) then
            call f%bind(['TEMP'], binding)
            call f%evaluate(binding, [temp], x, st)
        else
            call f%bind([character(len=4) :: ], binding)
            call f%evaluate(binding, [real(dp) :: ], x, st)
        end if
        if (st%failed() .and. present(temp)) then
            call set_error(st, st%code, b // '/' // key // ' at TEMP = ' // real_e13(temp) // &
                ': ' // st%message)
        else if (st%failed()) then
            call set_error(st, st%code, b // '/' // key // ': ' // st%message // &
                ' (parasol''s elements take the ' // b // ' functions of no parameter, ' // &
                'DEFI_CONSTANTE: give ELAS, or constant functions)')
        end if
    end subroutine material_value

end module model_plate_section
