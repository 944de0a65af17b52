!> Equation numbers, FEAP style: eq(d, node) is the equation of dof d of the
!> node, 0 for a constrained dof. Nodes are numbered in reverse Cuthill-McKee
!> order of the node graph so that the banded solver's band stays narrow
!> (for a chain or a ring: two nodes wide, whatever the input order).
!> eq(1:3, :) are the translations: the array a contact library takes.
module demo_numbering
  use demo_kinds, only: ndf
  implicit none
  private
  public :: rcm_order, number_equations, half_bandwidth

contains

  !> Reverse Cuthill-McKee order of n nodes linked by the pairs links(2, :).
  !> Each connected part starts from a pseudo-peripheral node (the last node
  !> reached by a breadth-first search from a node of least degree); neighbours
  !> are visited by increasing degree.
  subroutine rcm_order(n, links, order)
    integer, intent(in) :: n, links(:, :)
    integer, intent(out) :: order(n)
    integer, allocatable :: ptr(:), adj(:), deg(:), fill(:)
    logical, allocatable :: seen(:)
    integer :: i, k, a, b, nfound, start, seed, last

    allocate (deg(n), ptr(n + 1), seen(n), fill(n))
    deg = 0
    do k = 1, size(links, 2)
      a = links(1, k); b = links(2, k)
      if (a == b) cycle
      deg(a) = deg(a) + 1
      deg(b) = deg(b) + 1
    end do
    ptr(1) = 1
    do i = 1, n
      ptr(i + 1) = ptr(i) + deg(i)
    end do
    allocate (adj(ptr(n + 1) - 1))
    fill = ptr(1:n)
    do k = 1, size(links, 2)
      a = links(1, k); b = links(2, k)
      if (a == b) cycle
      adj(fill(a)) = b; fill(a) = fill(a) + 1
      adj(fill(b)) = a; fill(b) = fill(b) + 1
    end do

    seen = .false.
    nfound = 0
    do
      if (nfound == n) exit
      ! least-degree unvisited node, then the far end of its search
      seed = 0
      do i = 1, n
        if (.not. seen(i)) then
          if (seed == 0) then
            seed = i
          else if (deg(i) < deg(seed)) then
            seed = i
          end if
        end if
      end do
      call bfs(seed, nfound, last, .false.)
      start = last
      call bfs(start, nfound, last, .true.)
    end do
    order = order(n:1:-1)

  contains

    !> Breadth-first search from s over unvisited nodes; with keep, appends
    !> the visit order to `order` and marks the nodes; returns the last node.
    subroutine bfs(s, nf, last_node, keep)
      integer, intent(in) :: s
      integer, intent(inout) :: nf
      integer, intent(out) :: last_node
      logical, intent(in) :: keep
      integer, allocatable :: queue(:), nb(:)
      logical, allocatable :: mark(:)
      integer :: head, tail, v, j, t, w
      allocate (queue(n), mark(n))
      mark = seen
      head = 1; tail = 1
      queue(1) = s
      mark(s) = .true.
      do while (head <= tail)
        v = queue(head)
        head = head + 1
        nb = pack(adj(ptr(v):ptr(v + 1) - 1), .not. mark(adj(ptr(v):ptr(v + 1) - 1)))
        ! insertion sort by degree (node degrees are small)
        do j = 2, size(nb)
          w = nb(j)
          t = j - 1
          do while (t >= 1)
            if (deg(nb(t)) <= deg(w)) exit
            nb(t + 1) = nb(t)
            t = t - 1
          end do
          nb(t + 1) = w
        end do
        do j = 1, size(nb)
          if (mark(nb(j))) cycle   ! listed twice (parallel links)
          tail = tail + 1
          queue(tail) = nb(j)
          mark(nb(j)) = .true.
        end do
      end do
      last_node = queue(tail)
      if (keep) then
        order(nf + 1:nf + tail) = queue(1:tail)
        nf = nf + tail
        seen = mark
      end if
    end subroutine bfs
  end subroutine rcm_order

  !> eq(ndf, n_nodes) in node order `order`, skipping fixed dofs; neq equations.
  subroutine number_equations(order, fixed, eq, neq)
    integer, intent(in) :: order(:)
    logical, intent(in) :: fixed(:, :)
    integer, intent(out) :: eq(:, :), neq
    integer :: p, d, node
    eq = 0
    neq = 0
    do p = 1, size(order)
      node = order(p)
      do d = 1, ndf
        if (.not. fixed(d, node)) then
          neq = neq + 1
          eq(d, node) = neq
        end if
      end do
    end do
  end subroutine number_equations

  !> Half bandwidth (kl = ku, the structure is symmetric) of the matrix that
  !> couples the nodes of every link, each node with itself included.
  integer function half_bandwidth(eq, links) result(hb)
    integer, intent(in) :: eq(:, :), links(:, :)
    integer :: k, lo, hi
    hb = 0
    do k = 1, size(links, 2)
      lo = huge(1); hi = 0
      call span(eq(:, links(1, k)))
      call span(eq(:, links(2, k)))
      if (hi > 0) hb = max(hb, hi - lo)
    end do
  contains
    subroutine span(e)
      integer, intent(in) :: e(:)
      integer :: d
      do d = 1, size(e)
        if (e(d) > 0) then
          lo = min(lo, e(d))
          hi = max(hi, e(d))
        end if
      end do
    end subroutine span
  end function half_bandwidth

end module demo_numbering
